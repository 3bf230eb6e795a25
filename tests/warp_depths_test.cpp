// The depths a warp reads come from what the camera sees of the receivers, not from its planes.
#include <gtest/gtest.h>

#include <algorithm>

#include "registry/method.hpp"
#include "test_support.hpp"

using namespace shadowlab;

namespace {

// A lone box 100 units before the camera, wholly in view, under a sun from above and aside: the
// camera's near plane lies far before it.
Scene box_far_ahead(double camera_near) {
    Scene scene;
    scene.objects.push_back({.name = "box", .position = {0.0, 0.0, -100.0}, .size = {10.0, 6.0, 8.0}});
    scene.camera = {.position = {0.0, 20.0, 0.0},
                    .target = {0.0, 0.0, -100.0},
                    .fov_y_deg = 30.0,
                    .aspect = 16.0 / 9.0,
                    .near = camera_near,
                    .far = 1000.0};
    scene.light.direction = glm::normalize(glm::dvec3(-0.6, -1.0, 0.1));
    return scene;
}

double trace_value(const Trace& trace, const std::string& step, const std::string& name) {
    const Step* s = trace.find(step);
    if (!s) throw std::runtime_error("no step " + step);
    for (const NamedValue& v : s->values)
        if (v.name == name) return std::get<double>(v.value);
    throw std::runtime_error("no value " + name + " in " + step);
}

Trace lispsm_trace(const Scene& scene, const std::map<std::string, std::string>& settings = {}) {
    const Method& lispsm = *find_method("lispsm");
    Trace trace;
    const ShadowSetup setup =
        lispsm.compute_maps(gather_inputs(scene), resolve_settings("lispsm", lispsm.settings, settings), &trace);
    EXPECT_TRUE(setup.fallbacks.empty()) << describe(setup.fallbacks);
    return trace;
}

// The box's nearest corner along the view: the nearest receiver depth the camera sees.
double nearest_corner_depth(const Scene& scene) {
    double nearest = INFINITY;
    for (const glm::dvec3& c : scene.objects[0].world_bounds().corners())
        nearest = std::min(nearest, glm::dot(c - scene.camera.position, scene.camera.view_direction()));
    return nearest;
}

}  // namespace

TEST(WarpDepths, LispsmNearIsTheNearestReceiverSeenNotTheNearPlane) {
    const Scene scene = box_far_ahead(0.05);
    ASSERT_TRUE(scene.camera.frustum().contains(scene.objects[0].world_bounds().min));
    ASSERT_TRUE(scene.camera.frustum().contains(scene.objects[0].world_bounds().max));
    const Trace trace = lispsm_trace(scene);
    const double expected = nearest_corner_depth(scene);
    ASSERT_GT(expected, 50.0);  // 1,000 times the near plane
    EXPECT_NEAR(trace_value(trace, "n-opt", "z_n"), expected, 1e-9 * expected);
    EXPECT_EQ(trace_value(trace, "n-opt", "camera_near"), 0.05);
}

TEST(WarpDepths, LispsmWarpStaysWhenTheNearPlaneMovesBeforeTheReceivers) {
    const double n = trace_value(lispsm_trace(box_far_ahead(0.05)), "n-opt", "n");
    for (const double near : {0.5, 5.0, 50.0}) {
        const double moved = trace_value(lispsm_trace(box_far_ahead(near)), "n-opt", "n");
        EXPECT_NEAR(moved, n, 1e-9 * n) << "near " << near;
    }
}

// The virtual near plane: the eye's range starts near_hint of the way to the farthest receiver, so
// the warp weakens (n grows) as it moves in; off, the nearest receiver.
TEST(WarpDepths, VirtualNearPlaneIsAFractionOfTheReceiversRange) {
    const Scene scene = box_far_ahead(0.05);
    const Trace off = lispsm_trace(scene), hinted = lispsm_trace(scene, {{"near_hint", "0.5"}});
    const double near = trace_value(off, "n-opt", "receivers_near"), far = trace_value(off, "n-opt", "receivers_far");
    ASSERT_LT(near, far);
    EXPECT_NEAR(trace_value(hinted, "n-opt", "z_n"), near + 0.5 * (far - near), 1e-9 * far);
    EXPECT_GT(trace_value(hinted, "n-opt", "n"), trace_value(off, "n-opt", "n"));
}
