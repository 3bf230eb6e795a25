// Sample-distribution depth bounds: the camera's depth image reduced to the receivers it sees, in
// closed form on a scene seen straight down; cascades split across them cover every visible
// receiver pixel, and fall back by name when there is no depth image or nothing to see.
#include <gtest/gtest.h>

#include "maps/map_lookup.hpp"
#include "methods/cascades.hpp"
#include "metrics/measurement.hpp"
#include "reference/visible_depths.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

// A ground plane, a 3-high box on it and a 6-high post that receives no shadow, seen from 10 above.
Scene seen_from_above() {
    Scene scene;
    scene.objects.push_back({.name = "ground", .shape = Shape::plane, .size = {40.0, 1.0, 40.0}, .casts = false});
    scene.objects.push_back({.name = "box", .position = {0.0, 1.5, 0.0}, .size = {2.0, 3.0, 2.0}});
    scene.objects.push_back({.name = "post", .position = {3.0, 3.0, 0.0}, .size = {0.5, 6.0, 0.5}, .receives = false});
    scene.camera.position = {0.0, 10.0, 0.0};
    scene.camera.target = {0.0, 0.0, 0.0};
    scene.camera.up = {0.0, 0.0, -1.0};
    scene.camera.fov_y_deg = 40.0;
    scene.camera.aspect = 1.0;
    scene.camera.near = 0.1;
    scene.camera.far = 100.0;
    scene.light.direction = glm::normalize(glm::dvec3(0.3, -1.0, 0.2));
    return scene;
}

ShadowSetup visible_cascades(const ShadowInputs& in, const std::map<std::string, std::string>& set = {}) {
    std::map<std::string, std::string> all{{"bounds", "visible"}};
    all.insert(set.begin(), set.end());
    return compute_cascades(in, resolve_settings("cascades", cascades_settings(), all), nullptr);
}

}  // namespace

// Straight down, a surface's view depth is its height below the eye: the box top at 10 - 3, the
// ground at 10; the post is nearer (10 - 6) but receives nothing, so it is not counted.
TEST(VisibleDepths, TheReceiversSeenBoundTheRangeInClosedForm) {
    const Scene scene = seen_from_above();
    const DepthRange range = trace_receiver_depth_range(scene, tessellate(scene), 96, 96);
    EXPECT_NEAR(range.near, 7.0 * (1.0 - kVisibleDepthMargin), 1e-9);
    EXPECT_NEAR(range.far, 10.0 * (1.0 + kVisibleDepthMargin), 1e-9);
}

TEST(VisibleDepths, NothingSeenIsAnEmptyRange) {
    Scene scene = seen_from_above();
    scene.camera.target = {0.0, 20.0, 0.0};  // looking up at the sky
    scene.camera.up = {0.0, 0.0, 1.0};
    EXPECT_TRUE(trace_receiver_depth_range(scene, tessellate(scene), 32, 32).empty());
}

// The splits span the visible range, and every receiver pixel the camera sees reads a cascade
// whose tile holds it: the frustum's empty air before the first surface gets no cascade.
TEST(VisibleDepths, CascadesSplitTheVisibleRangeAndHoldEveryVisibleReceiver) {
    for (const char* file : {"default.json", "teaching.json", "box_on_plane.json"}) {
        const Scene scene = load_scene(source_path(std::string("data/scenes/") + file));
        const MeasureContext context = prepare_measurement(scene, 320, 180);
        ShadowInputs in = gather_inputs(scene);
        in.visible_depths = receiver_depth_range(scene, context.reference);
        for (const char* lambda : {"0.5", "1"}) {
            const ShadowSetup setup = visible_cascades(in, {{"lambda", lambda}});
            ASSERT_TRUE(setup.fallbacks.empty()) << file << ": " << describe(setup.fallbacks);
            EXPECT_EQ(setup.selection.split_depths.front(), in.visible_depths->near) << file;
            EXPECT_EQ(setup.selection.split_depths.back(), in.visible_depths->far) << file;
            EXPECT_GT(in.visible_depths->near, scene.camera.near) << file;
            const ReferenceImage& seen = context.reference;
            for (size_t i = 0; i < seen.visible.size(); ++i) {
                if (!seen.visible[i] || !scene.objects[seen.object[i]].receives) continue;
                const int map = select_map(setup, seen.position[i]);
                ASSERT_GE(map, 0) << file << " pixel " << i;
                ASSERT_TRUE(in_unit_cube(world_to_uvz(setup.maps[map], seen.position[i]), 1e-6))
                    << file << " pixel " << i;
            }
        }
    }
}

// Logarithmic splits over the frustum's 0.5 to 400 give the first cascade the air before the
// street; over the visible range every cascade serves pixels and the error drops (default scene).
TEST(VisibleDepths, LogarithmicSplitsOverTheVisibleRangeWasteNoCascade) {
    const MeasureContext context = prepare_measurement(load_scene(source_path("data/scenes/default.json")), 480, 270);
    const Method& method = method_or_throw("cascades");
    const auto measured = [&](const char* bounds) {
        return measure(context, method,
                       resolve_settings("cascades", method.settings, {{"bounds", bounds}, {"lambda", "1"}}), 2048,
                       -1.0);
    };
    const Measurement frustum = measured("frustum"), visible = measured("visible");
    EXPECT_EQ(frustum.by_map->maps[0].pixels, 0u) << "the frustum's first cascade sees only air";
    for (const MapShare& share : visible.by_map->maps) EXPECT_GT(share.pixels, 0u);
    EXPECT_LT(visible.error.misclassified, frustum.error.misclassified);
    EXPECT_TRUE(visible.fallbacks.empty()) << describe(visible.fallbacks);
}

TEST(VisibleDepths, WithoutADepthImageOrAReceiverCascadesFallBackByName) {
    const Scene scene = seen_from_above();
    ShadowInputs in = gather_inputs(scene);
    const ShadowSetup unmeasured = visible_cascades(in);
    EXPECT_TRUE(has_note(unmeasured.fallbacks, NoteKind::no_depth_image)) << describe(unmeasured.fallbacks);
    EXPECT_EQ(unmeasured.selection.split_depths.front(), scene.camera.near);
    in.visible_depths = DepthRange{};
    const ShadowSetup nothing_seen = visible_cascades(in);
    EXPECT_TRUE(has_note(nothing_seen.fallbacks, NoteKind::no_visible_receiver)) << describe(nothing_seen.fallbacks);
    EXPECT_EQ(nothing_seen.selection.split_depths.back(), scene.camera.far);
    EXPECT_TRUE(method_or_throw("cascades")
                    .wants_visible_depths(resolve_settings("cascades", cascades_settings(), {{"bounds", "visible"}})));
    EXPECT_FALSE(
        method_or_throw("cascades").wants_visible_depths(resolve_settings("cascades", cascades_settings(), {})));
}
