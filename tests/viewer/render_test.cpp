// What the views draw, checked on their pixels (under Xvfb): the map's depth image where
// world_to_uvz puts the caster, its texel grid, and the Error view's colours.
#include <array>
#include <iostream>
#include <gtest/gtest.h>

#include "views/error_colours.hpp"
#include "views/offscreen_view.hpp"
#include "scene/scene_loader.hpp"
#include "view_test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kWidth = 480, kHeight = 270;

}  // namespace

TEST(ShadowMapView, ShowsTheCasterWhereWorldToUvzPutsIt) {
    constexpr int n = 256;
    Scene scene = floating_box(kWidth, kHeight);
    scene.objects[0].casts = true;  // the ground is drawn into the map too, farther from the light
    const Inspection in = inspect(scene, "focused", n);
    const RgbImage image = render_view(in, view_or_throw("shadowmap"), {}, n, n);
    // One screen pixel per texel; texel row v is image row n - 1 - v.
    ASSERT_EQ(in.setup.maps.size(), 1u);  // the focused map: one tile, the whole texture
    auto pixel = [&](const glm::dvec3& p) {
        const glm::dvec3 uvz = world_to_uvz(in.setup.maps[0], p);
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
        const RgbImage image =
            render_view(inspect(scene, "focused", resolution), view_or_throw("shadowmap"), {}, 512, 512);
        size_t count = 0;
        for (int y = 0; y < image.height - 40; ++y)  // above the caption
            for (int x = 0; x < image.width; ++x) count += image.at(x, y)[2] > image.at(x, y)[0] + 60;
        return count;
    };
    EXPECT_GT(bluish_pixels(32), 512u * 20);  // 33 lines each way, 16 pixels apart
    EXPECT_EQ(bluish_pixels(1024), 0u);       // half a pixel per texel: no grid
}

// The Error view paints false light green and false shadow blue: planar shadows miss every
// shadow on a building of the default scene; z-fail volumes miss next to nothing on closed meshes.
TEST(ErrorView, PaintsMisclassifiedPixelsByKind) {
    auto painted = [&](const std::string& scene_name, const std::string& method) {
        Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/" + scene_name + ".json");
        scene.camera.aspect = static_cast<double>(kWidth) / kHeight;
        InspectionRequest request;
        request.method = method;
        request.image_width = kWidth;
        const RgbImage image = render_view(inspect_scene(scene, request), view_or_throw("error"), {}, kWidth, kHeight);
        std::array<size_t, 2> counts{};              // false light, false shadow
        for (int y = 0; y < image.height - 30; ++y)  // above the caption
            for (int x = 0; x < image.width; ++x) {
                const unsigned char* c = image.at(x, y);
                const error_colours::Colour colour{c[0], c[1], c[2]};
                counts[0] += colour == error_colours::kFalseLight;
                counts[1] += colour == error_colours::kFalseShadow;
            }
        return counts;
    };
    EXPECT_GT(painted("default", "planar")[0], 100u);
    EXPECT_GT(painted("default", "lispsm")[1], 0u);  // acne along shadow edges, dilated to be seen
    const auto volumes = painted("volumes", "volumes");
    EXPECT_LT(volumes[0] + volumes[1], 9 * kWidth * kHeight / 1000u);  // under 0.1 % of pixels, each painted 3 x 3
}
