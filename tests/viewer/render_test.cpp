// What the views draw, checked on their pixels (under Xvfb): shadows where the map puts them, the
// map's depth image where world_to_uvz puts the caster, and the GPU pass against the CPU lookup.
#include <array>
#include <iostream>
#include <gtest/gtest.h>

#include "methods/method.hpp"
#include "metrics/shadow_error.hpp"
#include "reference/exact_shadows.hpp"
#include "render/offscreen_view.hpp"
#include "scene/scene_loader.hpp"
#include "techniques/technique.hpp"
#include "view_test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kWidth = 480, kHeight = 270;

Inspection inspect(const Scene& scene, const std::string& method, int resolution = 1024) {
    InspectionRequest request;
    request.method = method;
    request.resolution = resolution;
    return inspect_scene(scene, request);
}

// The bias the metrics apply at reference pixel i: slope-scaled, from the seen side's normal.
double cpu_bias(const Inspection& in, const ReferenceImage& ref, size_t i) {
    const glm::dvec3& p = ref.position[i];
    const Light& light = in.scene.light;
    const glm::dvec3 along = light.is_directional() ? light.direction : glm::normalize(p - light.position);
    return slope_scaled_bias(in.map(), in.resolution, along, p, ref.facing[i]);
}

}  // namespace

class CameraViewOfEachMethod : public ::testing::TestWithParam<std::string> {};

// Every map method and every geometric technique (the stencil pass).
TEST_P(CameraViewOfEachMethod, GroundUnderTheBoxIsDarkerThanGroundFarFromIt) {
    const Scene scene = floating_box(kWidth, kHeight);
    const Inspection in = inspect(scene, GetParam());
    const RgbImage image = render_view(in, ViewKind::camera, {}, kWidth, kHeight);
    ASSERT_EQ(image.width, kWidth);
    const double under = brightness(image, pixel_of(scene.camera, {0.0, 0.0, 0.0}, kWidth, kHeight));
    const double away = brightness(image, pixel_of(scene.camera, {6.0, 0.0, -3.0}, kWidth, kHeight));
    EXPECT_GT(away, 80.0) << "the lit ground should be drawn";
    EXPECT_LT(under, 0.7 * away) << GetParam() << ": under the box " << under << ", away " << away;
}

INSTANTIATE_TEST_SUITE_P(AllMethods, CameraViewOfEachMethod, ::testing::ValuesIn([] {
                             std::vector<std::string> names;
                             for (const Method& m : all_methods()) names.push_back(m.name);
                             for (const Technique& t : all_techniques()) names.push_back(t.name);
                             return names;
                         }()));

TEST(ShadowMapView, ShowsTheCasterWhereWorldToUvzPutsIt) {
    constexpr int n = 256;
    Scene scene = floating_box(kWidth, kHeight);
    scene.objects[0].casts = true;  // the ground is drawn into the map too, farther from the light
    const Inspection in = inspect(scene, "focused", n);
    const RgbImage image = render_view(in, ViewKind::shadow_map, {}, n, n);
    // One screen pixel per texel; texel row v is image row n - 1 - v.
    auto pixel = [&](const glm::dvec3& p) {
        const glm::dvec3 uvz = world_to_uvz(in.map(), p);
        return glm::ivec2(static_cast<int>(uvz.x * n), n - 1 - static_cast<int>(uvz.y * n));
    };
    const glm::ivec2 box = pixel({0.0, 4.0, 0.0});
    const glm::ivec2 ground = pixel({7.0, 0.0, 2.0});
    ASSERT_TRUE(box.x > 8 && box.x < n - 8 && box.y > 8 && box.y < n - 8);
    EXPECT_LT(brightness(image, box, 2) + 30.0, brightness(image, ground, 2))
        << "the box top is nearer the light than the ground: darker";
}

// The texel grid appears once a texel spans 8 screen pixels, and not before.
TEST(ShadowMapView, TexelGridShowsOnlyWhenTexelsAreLarge) {
    const Scene scene = floating_box(kWidth, kHeight);
    auto bluish_pixels = [&](int resolution) {
        const RgbImage image = render_view(inspect(scene, "focused", resolution), ViewKind::shadow_map, {}, 512, 512);
        size_t count = 0;
        for (int y = 0; y < image.height - 40; ++y)  // above the caption
            for (int x = 0; x < image.width; ++x)
                count += image.at(x, y)[2] > image.at(x, y)[0] + 60;
        return count;
    };
    EXPECT_GT(bluish_pixels(32), 512u * 20);  // 33 lines each way, 16 pixels apart
    EXPECT_EQ(bluish_pixels(1024), 0u);       // half a pixel per texel: no grid
}

// The Error view paints false light green and false shadow magenta: planar shadows miss every
// shadow on a building of the default scene; z-fail volumes miss next to nothing on closed meshes.
TEST(ErrorView, PaintsMisclassifiedPixelsByKind) {
    auto painted = [&](const std::string& scene_name, const std::string& method) {
        Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/" + scene_name + ".json");
        scene.camera.aspect = static_cast<double>(kWidth) / kHeight;
        InspectionRequest request;
        request.method = method;
        request.image_width = kWidth;
        const RgbImage image = render_view(inspect_scene(scene, request), ViewKind::error, {}, kWidth, kHeight);
        std::array<size_t, 2> counts{};  // false light, false shadow
        for (int y = 0; y < image.height - 30; ++y)  // above the caption
            for (int x = 0; x < image.width; ++x) {
                const unsigned char* c = image.at(x, y);
                counts[0] += c[0] == 0 && c[1] == 255 && c[2] == 0;
                counts[1] += c[0] == 255 && c[1] == 0 && c[2] == 255;
            }
        return counts;
    };
    EXPECT_GT(painted("default", "planar")[0], 100u);
    const auto volumes = painted("volumes", "volumes");
    EXPECT_LT(volumes[0] + volumes[1], kWidth * kHeight / 1000u);
}

// Issue 5: the GPU pass and the CPU lookup agree on the visible pixels away from shadow edges.
class GpuAgreesWithCpu : public ::testing::TestWithParam<std::string> {};

TEST_P(GpuAgreesWithCpu, OnVisiblePixelsAwayFromShadowEdges) {
    Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/" + GetParam() + ".json");
    scene.camera.aspect = static_cast<double>(kWidth) / kHeight;
    for (const std::string method : {"focused", "lispsm", "xpsm"}) {
        const Inspection in = inspect(scene, method, 1024);
        ViewOptions options;
        options.lit_mask = true;
        const RgbImage gpu = render_view(in, ViewKind::camera, options, kWidth, kHeight);
        const ReferenceImage ref = exact_reference(in.scene, in.triangles, kWidth, kHeight);
        std::vector<int8_t> cpu(ref.visible.size(), -1);
        for (size_t i = 0; i < cpu.size(); ++i)
            if (ref.visible[i]) cpu[i] = in_shadow(in.depth, in.map(), ref.position[i], cpu_bias(in, ref, i)) ? 0 : 1;
        const Agreement a = agreement(gpu, cpu, ref);
        ASSERT_EQ(a.undrawn, 0u) << "the GPU drew nothing where the reference sees something";
        ASSERT_GT(a.compared, kWidth * kHeight / 4u);
        EXPECT_GE(a.share(), 0.995) << method << " on " << GetParam() << ": " << a.compared - a.agreed << " of "
                                    << a.compared << " pixels differ";
        RecordProperty(method + "_agreement", std::to_string(a.share()));  // in the XML report
        std::cout << method << " on " << GetParam() << ": GPU and CPU agree on " << a.agreed << " of " << a.compared
                  << " pixels away from edges\n";
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, GpuAgreesWithCpu, ::testing::Values("box_on_plane", "default", "spot"));
