// PSM and LiSPSM under a spot light (issue 14): PSM in the camera's post-perspective space, where the spot
// stays a point light; LiSPSM after the spot's own perspective, where its rays are parallel.
#include <gtest/gtest.h>

#include <cmath>

#include "metrics/measurement.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

ShadowSetup run(const std::string& method, const ShadowInputs& in) {
    const Method& m = *find_method(method);
    return m.compute_maps(in, resolve_settings(method, m.settings, {}), nullptr);
}

Scene spot_scene() { return load_scene(source_path("data/scenes/spot.json")); }

// A street lamp: a narrow spot high above a town, seen from the town's edge along its length, so that
// the view's perspective, not the spot's, sets where texels are needed (as under a directional light).
Scene street_lamp() {
    Scene scene = random_town(60, 100.0, 3);
    scene.camera.position = {0.0, 4.0, 50.0};
    scene.camera.target = {0.0, 0.0, 0.0};
    scene.camera.near = 0.5;
    scene.camera.far = 120.0;
    scene.light.type = LightType::spot;
    scene.light.position = {40.0, 120.0, -10.0};
    scene.light.direction = glm::normalize(glm::dvec3(0.0, 0.0, 10.0) - scene.light.position);
    scene.light.cone_deg = 50.0;
    return scene;
}

// x -> scale x + offset for every point of the scene, lengths times scale.
Scene moved(Scene scene, double scale, const glm::dvec3& offset) {
    for (SceneObject& o : scene.objects) {
        o.position = scale * o.position + offset;
        o.scale *= scale;
    }
    scene.camera.position = scale * scene.camera.position + offset;
    scene.camera.target = scale * scene.camera.target + offset;
    scene.camera.near *= scale;
    scene.camera.far *= scale;
    scene.light.position = scale * scene.light.position + offset;
    return scene;
}

// Points of every receiver's box on a 5^3 lattice that the camera sees and the spot's cone holds: points
// of V inside the cone, which a warp's region (the spot's reach of B ⊇ V) must hold.
std::vector<glm::dvec3> visible_points_in_cone(const ShadowInputs& in) {
    const double cos_half_cone = std::cos(glm::radians(in.light.cone_deg / 2));
    std::vector<glm::dvec3> points;
    for (const Aabb& box : in.receivers)
        for (int i = 0; i <= 4; ++i)
            for (int j = 0; j <= 4; ++j)
                for (int k = 0; k <= 4; ++k) {
                    const glm::dvec3 p = box.min + box.extent() * glm::dvec3(i, j, k) / 4.0;
                    const glm::dvec3 from_light = glm::normalize(p - in.light.position);
                    if (in.frustum.contains(p) && glm::dot(from_light, in.light.direction) > cos_half_cone)
                        points.push_back(p);
                }
    return points;
}

class SpotWarp : public ::testing::TestWithParam<std::string> {};

// The method's error with its default settings, slope-scaled bias, at `resolution`.
ShadowError measured(const MeasureContext& context, const std::string& name, int resolution) {
    const Method& m = method_or_throw(name);
    return measure(context, m, resolve_settings(name, m.settings, {}), resolution, -1.0).error;
}

}  // namespace

TEST_P(SpotWarp, WarpsWithoutFallback) {
    const ShadowSetup setup = run(GetParam(), gather_inputs(spot_scene()));
    EXPECT_TRUE(setup.fallbacks.empty()) << describe(setup.fallbacks);
    ASSERT_EQ(setup.maps.size(), 1u);
    EXPECT_TRUE(finite(setup.maps[0].world_to_uvz));
    // A warp, not the focused map's plain perspective from the spot.
    EXPECT_NE(setup.maps[0].world_to_uvz, run("focused", gather_inputs(spot_scene())).maps[0].world_to_uvz);
}

TEST_P(SpotWarp, VisiblePointsInTheConeMapIntoTheUnitCube) {
    const ShadowInputs in = gather_inputs(spot_scene());
    const ShadowSetup setup = run(GetParam(), in);
    const std::vector<glm::dvec3> points = visible_points_in_cone(in);
    ASSERT_GT(points.size(), 50u);
    for (const glm::dvec3& p : points) {
        const std::optional<glm::dvec3> uvz = setup_uvz(setup, p);
        ASSERT_TRUE(uvz && in_unit_cube(*uvz, 1e-6))
            << GetParam() << ": (" << p.x << ", " << p.y << ", " << p.z << ") maps to " << (uvz ? uvz->x : NAN) << ", "
            << (uvz ? uvz->y : NAN) << ", " << (uvz ? uvz->z : NAN);
    }
}

TEST_P(SpotWarp, DepthGrowsAwayFromTheLightAlongItsRays) {
    const ShadowInputs in = gather_inputs(spot_scene());
    const ShadowSetup setup = run(GetParam(), in);
    const ShadowMap& map = setup.maps[0];
    const double step = 1e-3 * in.scene_bounds.diagonal();
    for (const glm::dvec3& p : visible_points_in_cone(in)) {
        const glm::dvec3 ray = glm::normalize(p - in.light.position);
        const glm::dvec3 a = world_to_uvz(map, p), b = world_to_uvz(map, p + step * ray);
        ASSERT_GT(b.z, a.z) << GetParam();
        EXPECT_NEAR(a.x, b.x, 1e-9);  // a light ray keeps its texel
        EXPECT_NEAR(a.y, b.y, 1e-9);
    }
}

// The construction has no length or place of its own: far from the origin and scaled, the map takes the
// moved points where it took the original ones.
TEST_P(SpotWarp, MovedAndScaledSceneGivesTheSameMap) {
    constexpr double kScale = 37.0;
    const glm::dvec3 offset{1e3, -2e3, 3e3};
    const ShadowInputs here = gather_inputs(spot_scene());
    const ShadowInputs there = gather_inputs(moved(spot_scene(), kScale, offset));
    const ShadowSetup original = run(GetParam(), here), transformed = run(GetParam(), there);
    ASSERT_TRUE(transformed.fallbacks.empty()) << describe(transformed.fallbacks);
    for (const glm::dvec3& p : visible_points_in_cone(here)) {
        const glm::dvec3 expected = world_to_uvz(original.maps[0], p);
        const glm::dvec3 got = world_to_uvz(transformed.maps[0], kScale * p + offset);
        EXPECT_NEAR(got.x, expected.x, 1e-7);
        EXPECT_NEAR(got.y, expected.y, 1e-7);
        EXPECT_NEAR(got.z, expected.z, 1e-7);
    }
}

INSTANTIATE_TEST_SUITE_P(PsmAndLispsm, SpotWarp, ::testing::Values("psm", "lispsm"));

// Where the view's perspective sets the texels the eye needs (a narrow spot far above, a long view),
// LiSPSM in the spot's post-perspective space spreads them better than the focused map's perspective
// from the spot: the parameterization's part of Lloyd's m, over the pixels the camera sees, at the same
// resolution. (PSM, with the virtual camera's near plane at the eye's, over-warps here as it does for
// a directional light.)
TEST(SpotWarps, LispsmBeatsTheFocusedMapOnPerspectiveAliasingUnderAStreetLamp) {
    const MeasureContext context = prepare_measurement(street_lamp(), 320, 180);
    const AliasingStats focused = measured(context, "focused", 512).m_perspective,
                        lispsm = measured(context, "lispsm", 512).m_perspective;
    EXPECT_LT(lispsm.p95, focused.p95);
    EXPECT_LT(lispsm.mean, focused.mean);
}

// PSM takes the spot's position through the virtual camera like any point: L' = P V (position, 1).
// On the virtual camera's plane (w = 0) L' is a direction and the map an orthographic fit in PPS;
// behind the eye (w < 0) depth runs toward L' and is inverted. Both keep each light ray on one texel
// with depth growing away from the spot.
TEST(SpotWarps, PsmPutsTheSpotInPostPerspectiveSpace) {
    const Scene scene = spot_scene();
    const glm::dvec3 view = scene.camera.view_direction();
    const glm::dvec3 right = glm::normalize(glm::cross(view, scene.camera.up));
    for (const double along_view : {0.0, -6.0}) {  // on the eye's plane (nothing lies behind it), behind the eye
        Scene moved_light = scene;
        moved_light.light.position = scene.camera.position + 6.0 * right + along_view * view;
        moved_light.light.direction = glm::normalize(glm::dvec3(0, 1, -4) - moved_light.light.position);
        const ShadowInputs in = gather_inputs(moved_light);
        const Method& psm = method_or_throw("psm");
        Trace trace;
        const ShadowSetup setup = psm.compute_maps(in, resolve_settings("psm", psm.settings, {}), &trace);
        ASSERT_TRUE(setup.fallbacks.empty()) << along_view << ": " << describe(setup.fallbacks);
        const glm::dvec4 expected = *trace.frame(Space::ppls) * glm::dvec4(in.light.position, 1.0);
        const glm::dvec4 l_pps = std::get<glm::dvec4>(trace.find("psm-light")->values.front().value);
        EXPECT_NEAR(glm::distance(l_pps, expected), 0.0, 1e-9 * glm::length(expected));
        if (along_view == 0.0)
            EXPECT_TRUE(trace.find("psm-light-orthographic")) << "w = " << l_pps.w;
        else
            EXPECT_EQ(trace.find("psm-light-frustum")->title, "Inverted projection (Kozlov)");
        const double step = 1e-3 * in.scene_bounds.diagonal();
        for (const glm::dvec3& p : visible_points_in_cone(in)) {
            const glm::dvec3 ray = glm::normalize(p - in.light.position);
            const glm::dvec3 a = world_to_uvz(setup.maps[0], p), b = world_to_uvz(setup.maps[0], p + step * ray);
            ASSERT_GT(b.z, a.z) << along_view;
            EXPECT_NEAR(a.x, b.x, 1e-9);
            EXPECT_NEAR(a.y, b.y, 1e-9);
        }
    }
}

// On spot.json the spot's own perspective nearly matches the view's: LiSPSM's warp, set by how the eye's
// depth over the light's (t / z) varies across the map, still gains a little over the focused map.
TEST(SpotWarps, LispsmBeatsTheFocusedMapOnPerspectiveAliasingInTheSpotScene) {
    const MeasureContext context = prepare_measurement(spot_scene(), 640, 360);
    const AliasingStats focused = measured(context, "focused", 1024).m_perspective,
                        lispsm = measured(context, "lispsm", 1024).m_perspective;
    EXPECT_LT(lispsm.p95, focused.p95);
    EXPECT_LT(lispsm.max, focused.max);
}

// Lloyd's m itself (perspective times projection aliasing): both warps beat the focused spot map on
// its mean and p95 in the spot scene; PSM's gain is in the projection part (its own perspective
// stacks on the camera's: its perspective part alone is worse, see the README).
TEST(SpotWarps, BothWarpsBeatTheFocusedMapOnLloydsM) {
    const MeasureContext context = prepare_measurement(spot_scene(), 640, 360);
    const AliasingStats focused = measured(context, "focused", 1024).m;
    for (const char* warp : {"psm", "lispsm"}) {
        const AliasingStats warped = measured(context, warp, 1024).m;
        EXPECT_LT(warped.mean, focused.mean) << warp;
        EXPECT_LT(warped.p95, focused.p95) << warp;
    }
}
