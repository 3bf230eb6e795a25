// Shimmer: a map refitted to every frame's camera flips verdicts of fixed points; a map that does
// not depend on the camera flips none. The camera paths move as a player moves.
#include <gtest/gtest.h>

#include "metrics/shimmer.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using shadowlab::testing::source_path;

namespace {

MeasureContext small_context(const std::string& scene) {
    return prepare_measurement(load_scene(source_path("data/scenes/" + scene + ".json")), 160, 90);
}

Shimmer shimmer_of(const MeasureContext& c, const std::string& method, const CameraPath& path, int resolution = 256) {
    const Method& m = method_or_throw(method);
    return measure_shimmer(c, shimmer_samples(c), m, resolve_settings(m.name, m.settings, {}), resolution, -1.0, path);
}

}  // namespace

TEST(CameraPath, MovesAsAPlayerMoves) {
    Camera start;
    start.position = {0, 2, 10};
    start.target = {0, 0, 0};
    const glm::dvec3 right = glm::normalize(glm::cross(start.view_direction(), start.up));
    const Camera moved = camera_at(start, {CameraPath::Kind::translate, 10, 0.5}, 4);
    EXPECT_NEAR(glm::distance(moved.position, start.position + 2.0 * right), 0.0, 1e-12);
    EXPECT_NEAR(glm::distance(moved.target, start.target + 2.0 * right), 0.0, 1e-12);

    const Camera dollied = camera_at(start, {CameraPath::Kind::dolly, 10, 1.0}, 3);
    EXPECT_NEAR(glm::distance(dollied.position, start.position + 3.0 * start.view_direction()), 0.0, 1e-12);

    const Camera turned = camera_at(start, {CameraPath::Kind::rotate, 10, 30.0}, 3);  // 90° about +y
    EXPECT_EQ(turned.position, start.position);
    EXPECT_NEAR(glm::distance(turned.target, start.position), glm::distance(start.target, start.position), 1e-12);
    const auto horizontal = [](const glm::dvec3& v) { return glm::dvec2(v.x, v.z); };  // turned about +y
    EXPECT_NEAR(glm::dot(horizontal(turned.target - start.position), horizontal(start.target - start.position)), 0.0,
                1e-9);
    EXPECT_NEAR(turned.target.y, start.target.y, 1e-12);

    // Automatic steps: 0.5 % of the distance to the target, 0.25° per frame.
    EXPECT_NEAR(step_per_frame({CameraPath::Kind::dolly, 10, 0.0}, start), 0.005 * glm::length(start.position), 1e-12);
    EXPECT_EQ(step_per_frame({CameraPath::Kind::rotate, 10, 0.0}, start), 0.25);
    EXPECT_EQ(camera_path_named("dolly"), CameraPath::Kind::dolly);
    EXPECT_FALSE(camera_path_named("orbit"));
}

// The uniform map covers the scene's bounds whatever the camera does: no verdict can flip.
TEST(Shimmer, AMapIndependentOfTheCameraNeverFlips) {
    const MeasureContext c = small_context("default");
    const Shimmer s = shimmer_of(c, "uniform", {CameraPath::Kind::translate, 12, 0.0});
    EXPECT_GT(s.transitions(), 1000u);
    EXPECT_EQ(s.flips(), 0u);
}

// The focused map is refitted to each frame's view: its texel grid slides under the fixed points,
// and verdicts along shadow edges flip.
TEST(Shimmer, AMapRefittedToEveryFrameFlipsVerdicts) {
    const MeasureContext c = small_context("default");
    const Shimmer s = shimmer_of(c, "focused", {CameraPath::Kind::translate, 12, 0.0});
    EXPECT_GT(s.transitions(), 1000u);
    EXPECT_GT(s.flips(), 0u);
    EXPECT_LT(s.share(), 0.2) << "only points near shadow edges flip";
    for (const FrameShimmer& f : s.frames) EXPECT_LE(f.wrong, f.judged);
}

TEST(Shimmer, AGeometricTechniqueHasNoMapToShimmer) {
    const MeasureContext c = small_context("box_on_plane");
    EXPECT_THROW(shimmer_of(c, "volumes", {CameraPath::Kind::translate, 2, 0.0}), std::invalid_argument);
}

// Stabilized cascades (seed 003's snapping): a sideways path moves every light box by whole texels
// and keeps each point's view depth, so no verdict flips; without the snap the boxes slide by
// fractions of a texel and verdicts along shadow edges flip.
TEST(Shimmer, StabilizedCascadesFlipNoVerdictAlongASidewaysPath) {
    const MeasureContext c = small_context("teaching");
    const Method& cascades = method_or_throw("cascades");
    const CameraPath path{CameraPath::Kind::translate, 12, 0.0};
    auto flips = [&](const std::string& stabilize) {
        const Settings s =
            resolve_settings("cascades", cascades.settings, {{"fit", "sphere"}, {"stabilize", stabilize}});
        return measure_shimmer(c, shimmer_samples(c), cascades, s, 512, -1.0, path);
    };
    const Shimmer stable = flips("on"), sliding = flips("off");
    EXPECT_GT(stable.transitions(), 1000u);
    EXPECT_EQ(stable.flips(), 0u);
    EXPECT_GT(sliding.flips(), 0u);
}
