// LogPSM (methods/logpsm over maps/log_perspective_projection): the log warp's closed forms, the
// sagitta of its curved images of straight edges against the sampled curve, the split that follows
// them, its named fallback, and Lloyd's claim on the overhead view.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <glm/gtc/matrix_transform.hpp>

#include "maps/clip_conventions.hpp"
#include "maps/log_perspective_projection.hpp"
#include "maps/map_lookup.hpp"
#include "methods/logpsm.hpp"
#include "methods/shadow_inputs.hpp"
#include "metrics/measurement.hpp"
#include "raster/paraboloid_edges.hpp"
#include "scene/scene_loader.hpp"
#include "scene/tessellation.hpp"
#include "sampled_bow.hpp"
#include "step_values.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

Scene shipped(const std::string& name) { return load_scene(source_path("data/scenes/" + name + ".json")); }

ShadowSetup logpsm(const Scene& scene, Trace* trace = nullptr) {
    const Method& method = method_or_throw("logpsm");
    return method.compute_maps(gather_inputs(scene), resolve_settings("logpsm", method.settings, {}), trace);
}

// The point at fraction t along a–b under the map: its (u, v).
glm::dvec2 image_at(const ShadowMap& map, const glm::dvec3& a, const glm::dvec3& b, double t) {
    return glm::dvec2(world_to_uvz(map, glm::mix(a, b, t)));
}

double sampled_sagitta(const ShadowMap& map, const glm::dvec3& a, const glm::dvec3& b, int samples) {
    return sampled_bow([&](double t) { return image_at(map, a, b, t); }, samples);
}

}  // namespace

// v = log(w / near) / log(far / near): the rows at near, the geometric mean and far are 0, ½ and 1,
// and w = near (far / near)^v inverts it.
TEST(LogPerspectiveKind, VIsTheLogOfTheDistanceBetweenNearAndFar) {
    const LogWarp warp{.near = 2.0, .far = 200.0};
    EXPECT_NEAR(log_warp_v(warp, 2.0), 0.0, 1e-15);
    EXPECT_NEAR(log_warp_v(warp, 20.0), 0.5, 1e-15);
    EXPECT_NEAR(log_warp_v(warp, 200.0), 1.0, 1e-15);
    for (double v : {0.0, 0.1, 0.37, 0.9, 1.0}) EXPECT_NEAR(log_warp_v(warp, log_warp_w(warp, v)), v, 1e-14);
    EXPECT_EQ(log_warp_v(warp, -5.0), log_warp_v(warp, kLogClipShare * warp.near)) << "behind the clip plane: on it";
}

// The method on the light overhead and the camera level (γ = 90°, the eye's range from the near plane):
// η = 1 puts the warp's centre at the eye's depth, so the map's w is the view depth z and v =
// log(z / z_n) / log(z_f / z_n) on the ground ahead: texel rows as deep as z (∂v/∂z = 1 / (z log(z_f / z_n))),
// Lloyd's F_lp. The perspective alone would give ∂v_p/∂z ∝ 1 / z².
TEST(LogPsm, TexelRowsAreAsDeepAsTheViewDepthAlongTheView) {
    const Scene scene = shipped("light_overhead");
    Trace trace;
    const ShadowSetup setup = logpsm(scene, &trace);
    ASSERT_EQ(setup.maps.size(), 1u);
    ASSERT_TRUE(setup.fallbacks.empty()) << describe(setup.fallbacks);
    const ShadowMap& map = setup.maps[0];
    ASSERT_EQ(map.projection, Projection::log_perspective);
    const double z_n = step_value(trace, "logpsm-n", "z_n"), z_f = step_value(trace, "logpsm-n", "z_f");
    EXPECT_NEAR(map.log_warp.far / map.log_warp.near, z_f / z_n, 1e-9 * z_f / z_n);
    const glm::dvec3 ahead = scene.camera.view_direction();
    ASSERT_NEAR(ahead.y, 0.0, 1e-12) << "the camera looks level";
    int checked = 0;
    for (double z = 5.0; z < 0.9 * z_f; z *= 1.5, ++checked) {
        const glm::dvec3 ground = glm::dvec3(scene.camera.position.x, 0.0, scene.camera.position.z) + z * ahead;
        EXPECT_NEAR(world_to_uvz(map, ground).y, std::log(z / z_n) / std::log(z_f / z_n), 1e-9) << "z = " << z;
        const double density = uv_derivative(map, ground, ahead).y;
        EXPECT_NEAR(density * z * std::log(z_f / z_n), 1.0, 1e-9) << "z = " << z;
    }
    EXPECT_GE(checked, 5);
}

// The closed form of the sagitta (the bow of u = α + β / w, v = log(w / near) / L at the logarithmic
// mean of 1 / w) against the image sampled finely, on edges across the overhead view's map, some
// crossing the clip plane behind the warp's near end.
TEST(LogPerspectiveEdges, ClosedFormSagittaMatchesTheSampledCurve) {
    const Scene scene = shipped("overhead_view");
    const ShadowSetup setup = logpsm(scene);
    ASSERT_EQ(setup.maps.size(), 1u);
    const ShadowMap& map = setup.maps[0];
    ASSERT_EQ(map.projection, Projection::log_perspective);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.05, 0.95), d(0.05, 0.95);
    int bowed = 0;
    for (int i = 0; i < 200; ++i) {
        const ProjectionKind& kind = projection_kind(map);
        const glm::dvec3 a = kind.world_of(map, {u(rng), u(rng), d(rng)});
        const glm::dvec3 b = kind.world_of(map, {u(rng), u(rng), d(rng)});
        const double closed = kind.edge_sagitta(map, a, b);
        EXPECT_EQ(closed, kind.edge_sagitta(map, b, a)) << "symmetric to the last bit";
        const double sampled = sampled_sagitta(map, a, b, 20000);
        EXPECT_GE(closed, sampled - 1e-9);
        EXPECT_NEAR(closed, sampled, 1e-6 + 1e-3 * closed);
        bowed += closed > 1e-3;
    }
    EXPECT_GT(bowed, 50) << "most edges across the map bow";
    const glm::dvec3 lit = projection_kind(map).world_of(map, {0.5, 0.2, 0.5});
    EXPECT_LT(projection_kind(map).edge_sagitta(map, lit, lit + 5.0 * scene.light.direction), 1e-12)
        << "an edge along the light keeps its u, v: one point";
}

// Splitting the overhead view's casters for the map: every edge of the split mesh bows at most the
// target, and there are more triangles than before (the town's long edges bow by texels).
TEST(LogPerspectiveEdges, SplitCastersBowUnderTheTarget) {
    const Scene scene = shipped("overhead_view");
    const ShadowSetup setup = logpsm(scene);
    ASSERT_EQ(setup.maps.size(), 1u);
    const ShadowMap& map = setup.maps[0];
    ASSERT_TRUE(splits_casters(map));
    const WorldTriangles triangles = tessellate(scene);
    const std::vector<bool> casters = caster_flags(scene);
    constexpr int kResolution = 2048;
    const WorldTriangles split = split_casters(triangles, casters, map, kResolution);
    size_t caster_triangles = 0;
    double worst_before = 0.0;
    for (size_t i = 0; i < triangles.triangles.size(); ++i) {
        if (!casters[triangles.object[i]]) continue;
        ++caster_triangles;
        for (int k = 0; k < 3; ++k)
            worst_before =
                std::max(worst_before,
                         edge_sagitta_texels(map, triangles.vertices[triangles.triangles[i][k]],
                                             triangles.vertices[triangles.triangles[i][(k + 1) % 3]], kResolution));
    }
    ASSERT_GT(caster_triangles, 100u);
    EXPECT_GT(worst_before, 1.0) << "the casters' edges bow by texels before the split";
    EXPECT_GT(split.triangles.size(), caster_triangles);
    double worst = 0.0;
    for (const auto& t : split.triangles)
        for (int k = 0; k < 3; ++k)
            worst = std::max(
                worst, edge_sagitta_texels(map, split.vertices[t[k]], split.vertices[t[(k + 1) % 3]], kResolution));
    EXPECT_LE(worst, map.max_sagitta_texels);
    std::cout << caster_triangles << " caster triangles, worst sagitta " << worst_before << " texels; split into "
              << split.triangles.size() << ", worst " << worst << "\n";
}

// A view whose depths span under e^0.1 (the camera's range 100..105 over the ground): the log warp
// would be nearly linear and beyond float's precision on the GPU; the perspective warp alone, named.
TEST(LogPsm, AShortLogRangeKeepsThePerspectiveAloneUnderANamedNote) {
    Scene scene = shipped("light_overhead");
    scene.camera.near = 100.0;
    scene.camera.far = 105.0;
    const ShadowSetup setup = logpsm(scene);
    ASSERT_EQ(setup.maps.size(), 1u);
    EXPECT_TRUE(has_note(setup.fallbacks, NoteKind::log_range_short)) << describe(setup.fallbacks);
    EXPECT_EQ(setup.maps[0].projection, Projection::linear);
}

// The claim (Lloyd et al. 2008's comparison): on the overhead view (far / near = 1,000, the sun
// low), at equal texels (one 2048² map each) over the same focus region (the body B, each method's
// default), LogPSM's greatest perspective aliasing m is below LiSPSM's and TSM's.
TEST(LogPsm, MaximumPerspectiveErrorIsBelowLispsmsAndTsmsOnTheOverheadView) {
    const MeasureContext context = prepare_measurement(shipped("overhead_view"), 640, 360);
    std::map<std::string, double> m_max;
    for (const std::string name : {"logpsm", "lispsm", "tsm"}) {
        const Method& method = method_or_throw(name);
        const Measurement measured = measure(context, method, resolve_settings(name, method.settings, {}), 2048, -1.0);
        ASSERT_TRUE(measured.fallbacks.empty()) << name << ": " << describe(measured.fallbacks);
        ASSERT_GT(measured.error.receiver_pixels, 100'000u);
        m_max[name] = measured.error.m_perspective.max;
        std::cout << name << ": m_perspective max " << m_max[name] << ", mean " << measured.error.m_perspective.mean
                  << "\n";
    }
    EXPECT_LT(m_max["logpsm"], m_max["lispsm"]);
    EXPECT_LT(m_max["logpsm"], m_max["tsm"]);
}

// The storage factor (metrics/storage_bound.hpp) on the same view at 2048²: the methods that fit one
// map to the whole body B, held to one bound (the view's fewest texels for m = 1 over the receivers in
// shadow, which each of them covers), so that a higher efficiency is fewer texels needed. Each is at
// most 1 and LogPSM's is the highest (its max perspective m the lowest at equal texels, above).
TEST(LogPsm, StorageEfficiencyIsTheHighestOfTheWholeBodyMethodsOnTheOverheadView) {
    MeasureContext context = prepare_measurement(shipped("overhead_view"), 640, 360);
    add_storage_bounds(context);
    const double bound = context.storage_bounds->shadowed_receivers;
    ASSERT_GT(bound, 0.0);
    std::map<std::string, double> efficiency;
    for (const std::string name : {"focused", "psm", "lispsm", "tsm", "xpsm", "logpsm"}) {
        const Method& method = method_or_throw(name);
        const Measurement m = measure(context, method, resolve_settings(name, method.settings, {}), 2048, -1.0);
        ASSERT_TRUE(m.storage) << name;
        EXPECT_LE(m.storage->efficiency, 1.0) << name;
        efficiency[name] = bound / m.storage->needed;
        EXPECT_LE(efficiency[name], 1.0) << name;
        std::cout << name << ": needs " << m.storage->needed << " texels, efficiency " << efficiency[name] << "\n";
    }
    for (const auto& [name, e] : efficiency) {
        if (name == "logpsm") continue;
        EXPECT_GT(efficiency["logpsm"], e) << name;
    }
}
