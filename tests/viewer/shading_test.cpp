// Shadows that read (render/surface_shading.hpp), on the teaching scene's Camera view: a shadow is
// tinted blue-violet and darker, a surface facing away from the light stays neutral grey, and the
// map pass and the stencil pass agree on where the shadows are. And `render --light AZ,EL`, which
// turns the sun as the window's Controls panel does.
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <gtest/gtest.h>
#include <vtkImageData.h>

#include "render/surface_shading.hpp"
#include "render_command.hpp"
#include "scene/image_size.hpp"
#include "scene/light.hpp"
#include "scene/scene_loader.hpp"
#include "view_test_support.hpp"
#include "views/offscreen_view.hpp"
#include "views/polydata.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kWidth = 480, kHeight = 270;

Scene teaching() { return shipped_scene("teaching", kWidth, kHeight); }

Inspection inspect_at_image_size(const Scene& scene, const std::string& method) {
    InspectionRequest request;
    request.method = method;
    request.resolution = 2048;
    request.image_width = kWidth;  // a technique judges, and the stencil pass draws, this image
    request.image_height = kHeight;
    return inspect_scene(scene, request);
}

// The light reaching a set of pixels: their mean colour divided by their objects' albedo, per
// channel, so that surfaces of different colours compare. Neutral light has blue / red = 1.
struct ReachingLight {
    glm::dvec3 sum{0.0};
    size_t pixels = 0;
    glm::dvec3 mean() const { return sum / static_cast<double>(pixels); }
    double blue_over_red() const { return mean().b / mean().r; }
    double value() const { return (mean().r + mean().g + mean().b) / 3.0; }
};

// Which pixels a test compares: away from edges (the 3x3 neighbourhood on one object, with one
// verdict in the lit mask), then sorted by what the scene says about them.
enum class Kind { shadowed_ground, lit_ground, facing_away, other };

struct Classified {
    ReachingLight shadowed_ground, lit_ground, facing_away;
};

Classified classify(const Scene& scene, const ReferenceImage& ref, const RgbImage& shaded, const RgbImage& mask) {
    const std::vector<glm::dvec3> albedo = object_colours(scene);
    const auto in_shadow = [&](int x, int y) { return mask.at(x, y)[0] < 128; };
    Classified out;
    for (int y = 1; y < kHeight - 1; ++y)
        for (int x = 1; x < kWidth - 1; ++x) {
            const size_t i = static_cast<size_t>(y) * kWidth + x;
            if (!ref.visible[i]) continue;
            bool interior = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    interior = interior && ref.object[i + dy * kWidth + dx] == ref.object[i] &&
                               in_shadow(x + dx, y + dy) == in_shadow(x, y);
            if (!interior) continue;
            const bool ground = scene.objects[ref.object[i]].shape == Shape::plane;
            ReachingLight* light = ground ? (in_shadow(x, y) ? &out.shadowed_ground : &out.lit_ground)
                                          : (ref.facing[i] < -0.2f ? &out.facing_away : nullptr);
            if (!light) continue;
            const unsigned char* c = shaded.at(x, y);
            light->sum += glm::dvec3(c[0], c[1], c[2]) / (255.0 * albedo[ref.object[i]]);
            ++light->pixels;
        }
    return out;
}

RgbImage lit_mask(const Inspection& in) {
    ViewOptions options;
    options.lit_mask = true;
    return render_view(in, view_or_throw("camera"), options, kWidth, kHeight);
}

}  // namespace

class TeachingSceneShading : public ::testing::TestWithParam<std::string> {};

// Issue: shadowed ground and unlit walls looked alike. Now they differ in hue, and a shadow is
// plainly darker than the lit ground.
TEST_P(TeachingSceneShading, ShadowIsTintedAndFacingAwayIsNeutral) {
    const Scene scene = teaching();
    const Inspection in = inspect_at_image_size(scene, GetParam());
    const RgbImage shaded = render_view(in, view_or_throw("camera"), {}, kWidth, kHeight);
    const Classified c = classify(scene, in.reference(kWidth, kHeight), shaded, lit_mask(in));
    ASSERT_GT(c.shadowed_ground.pixels, 2000u) << "the teaching scene shows its shadows on the ground";
    ASSERT_GT(c.lit_ground.pixels, 10000u);
    ASSERT_GT(c.facing_away.pixels, 300u) << "and faces turned from the sun";
    const double tint = kShadowTint.b / kShadowTint.r;
    EXPECT_NEAR(c.shadowed_ground.blue_over_red(), tint, 0.15) << GetParam();
    EXPECT_NEAR(c.facing_away.blue_over_red(), 1.0, 0.1) << GetParam();
    EXPECT_NEAR(c.lit_ground.blue_over_red(), 1.0, 0.1) << GetParam();
    EXPECT_LT(c.shadowed_ground.value(), 0.6 * c.lit_ground.value()) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(MapAndStencilPass, TeachingSceneShading, ::testing::Values("focused", "volumes"));

// The two passes shadow the same ground: their lit masks differ on few ground pixels.
TEST(TeachingSceneShading, MapAndVolumesShadowTheSameGround) {
    const Scene scene = teaching();
    const Inspection map = inspect_at_image_size(scene, "focused");
    const Inspection volumes = inspect_at_image_size(scene, "volumes");
    const RgbImage a = lit_mask(map), b = lit_mask(volumes);
    const ReferenceImage& ref = map.reference(kWidth, kHeight);
    size_t ground = 0, differ = 0, shadowed = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const size_t i = static_cast<size_t>(y) * kWidth + x;
            if (!ref.visible[i] || scene.objects[ref.object[i]].shape != Shape::plane) continue;
            ++ground;
            shadowed += a.at(x, y)[0] < 128;
            differ += (a.at(x, y)[0] < 128) != (b.at(x, y)[0] < 128);
        }
    ASSERT_GT(shadowed, ground / 50) << "some ground is shadowed";
    EXPECT_LT(differ, ground / 100) << differ << " of " << ground << " ground pixels";
}

// The conversion the window's sliders use, and its inverse.
TEST(LightAngles, RoundTripAndTheControlsPanelsAxes) {
    const glm::dvec3 from_x = light_direction_from_angles(0.0, 0.0), from_z = light_direction_from_angles(90.0, 0.0);
    EXPECT_NEAR(glm::distance(from_x, glm::dvec3(-1.0, 0.0, 0.0)), 0.0, 1e-12) << "azimuth 0: from +x";
    EXPECT_NEAR(glm::distance(from_z, glm::dvec3(0.0, 0.0, -1.0)), 0.0, 1e-12) << "azimuth 90: from +z";
    EXPECT_NEAR(light_direction_from_angles(123.0, 90.0).y, -1.0, 1e-12) << "elevation 90: straight down";
    for (double azimuth : {0.0, 37.0, 181.0, 359.0})
        for (double elevation : {-30.0, 5.0, 35.0, 89.0}) {
            const glm::dvec3 d = light_direction_from_angles(azimuth, elevation);
            EXPECT_NEAR(glm::length(d), 1.0, 1e-12);
            const LightAngles back = light_angles(3.0 * d);  // any length
            EXPECT_NEAR(back.azimuth_deg, azimuth, 1e-9);
            EXPECT_NEAR(back.elevation_deg, elevation, 1e-9);
        }
}

namespace {

RenderOptions box_on_plane_render(const std::string& light, const std::string& out) {
    RenderOptions options;
    options.scene_file = std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/box_on_plane.json";
    options.width = kWidth;
    options.height = kHeight;
    options.resolution = 1024;
    options.light = light;
    options.out = out;
    return options;
}

}  // namespace

// --light 0,35 puts the sun at +x: the box's shadow falls toward -x; --light 180,35 the other way.
TEST(RenderLight, TurnsTheSunAsTheControlsPanelDoes) {
    const std::string out = ::testing::TempDir() + "render_light_" + std::to_string(getpid()) + ".png";
    const Scene scene = shipped_scene("box_on_plane", kWidth, kHeight);
    const glm::ivec2 size = image_size_within(scene.camera, kWidth, kHeight);
    const glm::ivec2 minus_x = pixel_of(scene.camera, {-2.6, 0.0, 0.0}, size.x, size.y);
    const glm::ivec2 plus_x = pixel_of(scene.camera, {2.6, 0.0, 0.0}, size.x, size.y);
    for (const auto& [angles, shadow_side_negative] : {std::pair{"0,35", true}, std::pair{"180,35", false}}) {
        run_render(box_on_plane_render(angles, out));
        const RgbImage image = read_png(out);
        const double left = brightness(image, minus_x), right = brightness(image, plus_x);
        if (shadow_side_negative)
            EXPECT_LT(left, 0.7 * right) << angles;
        else
            EXPECT_LT(right, 0.7 * left) << angles;
    }
    std::filesystem::remove(out);
}

TEST(RenderLight, BadValuesAreRefusedWithTheOptionsName) {
    for (const char* bad : {"abc", "35", "10,95", "nan,20", "10,20,30"}) {
        try {
            run_render(box_on_plane_render(bad, "/tmp/never.png"));
            ADD_FAILURE() << bad << " accepted";
        } catch (const std::invalid_argument& e) {
            EXPECT_EQ(std::string(e.what()).rfind("--light: ", 0), 0u) << e.what();
        }
    }
    RenderOptions preset = box_on_plane_render("", "/tmp/never.png");
    preset.preset = "top";
    EXPECT_THROW(run_render(preset), std::invalid_argument);
    EXPECT_FALSE(std::filesystem::exists("/tmp/never.png"));
}
