// The stability sweep: 10,000 random light and camera configurations, hard cases included
// (light almost parallel to the view from behind and from in front, light overhead, casters behind
// the viewer, far/near up to 1e5). Every method must give finite maps, only named fallbacks, and
// keep visible receivers inside the unit cube.
#include <gtest/gtest.h>

#include "geometry/intersection_body.hpp"
#include "methods/method.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

struct Configuration {
    Camera camera;
    Light light;
};

glm::dvec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<double> n;
    glm::dvec3 v;
    do v = {n(rng), n(rng), n(rng)}; while (glm::length(v) < 1e-6);
    return glm::normalize(v);
}

// A direction at `angle` radians from `axis`.
glm::dvec3 tilted(const glm::dvec3& axis, double angle, std::mt19937& rng) {
    glm::dvec3 side = glm::cross(axis, random_unit(rng));
    side = glm::normalize(side);
    return std::cos(angle) * axis + std::sin(angle) * side;
}

Configuration random_configuration(int i, std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Configuration c;
    c.camera.position = {(u(rng) - 0.5) * 500, 0.5 + 30 * u(rng) * u(rng), (u(rng) - 0.5) * 500};
    glm::dvec3 view = random_unit(rng);
    view.y = -std::abs(view.y) * 0.5;  // mostly toward the ground and horizon
    c.camera.target = c.camera.position + glm::normalize(view);
    c.camera.near = std::pow(10.0, -2.0 + 2.0 * u(rng));
    c.camera.far = c.camera.near * std::pow(10.0, 1.0 + 4.0 * u(rng));  // far/near from 10 to 1e5
    c.camera.fov_y_deg = 20 + 100 * u(rng);
    const glm::dvec3 v = c.camera.view_direction();
    const double tiny = std::pow(10.0, -6.0 + 4.0 * u(rng));  // 1e-6 to 1e-2 rad
    switch (i % 5) {
        case 0: c.light.direction = tilted(v, tiny, rng); break;   // from behind the viewer
        case 1: c.light.direction = tilted(-v, tiny, rng); break;  // toward the viewer
        case 2: c.light.direction = {0, -1, 0}; break;             // overhead
        case 3:  // casters behind the viewer: light from behind, camera at the town's edge
            c.camera.position = {0, 2, 260};
            c.camera.target = {0, 1.5, 250};
            c.light.direction = glm::normalize(glm::dvec3(0.1 * (u(rng) - 0.5), -0.3 * u(rng) - 0.05, -1));
            break;
        default: c.light.direction = random_unit(rng); break;
    }
    return c;
}

}  // namespace

TEST(StabilitySweep, TenThousandConfigurationsGiveFiniteMapsAndNamedFallbacks) {
    const Scene town = random_town(150, 500.0, 11);
    const std::vector<ObjectBox> boxes = object_boxes(town);
    std::mt19937 rng(2026);
    int fallbacks = 0;
    for (int i = 0; i < 10000; ++i) {
        const Configuration c = random_configuration(i, rng);
        const ShadowInputs in = gather_inputs(c.camera, c.light, boxes);
        for (const Method& method : all_methods()) {
            const ShadowSetup setup = method.compute(in, resolve_settings(method.name, method.settings, {}), nullptr);
            ASSERT_EQ(setup.maps.size(), 1u);
            ASSERT_TRUE(finite(setup.maps[0].world_to_uvz)) << method.name << " configuration " << i;
            ASSERT_TRUE(std::isfinite(setup.maps[0].z_bias_scale));
            if (setup.fallback) {
                ++fallbacks;
                ASSERT_TRUE(is_named_fallback(*setup.fallback)) << *setup.fallback;
            }
            const double tol = 1e-7 * in.scene_bounds.diagonal();
            for (const glm::dvec3& p : in.receiver_points())
                if (in.frustum.contains(p, -tol))
                    ASSERT_TRUE(in_unit_cube(world_to_uvz(setup.maps[0], p), 1e-6)) << method.name << " configuration " << i;
        }
    }
    RecordProperty("fallbacks", fallbacks);
}

TEST(StabilitySweep, FloatClipperAgreesWithExactKernelOnRandomConfigurations) {
    const Scene town = random_town(100, 500.0, 5);
    const std::vector<ObjectBox> boxes = object_boxes(town);
    std::mt19937 rng(99);
    int compared = 0;
    for (int i = 0; i < 300; ++i) {
        const Configuration c = random_configuration(i, rng);
        const ShadowInputs in = gather_inputs(c.camera, c.light, boxes);
        const BodyInput input{in.frustum, in.scene_bounds, in.light.homogeneous()};
        const IntersectionBody exact = intersection_body(input, BodyKernel::epeck);
        const IntersectionBody fast = intersection_body(input, BodyKernel::float_clipper);
        const double volume = exact.body.volume();
        const double scale = in.scene_bounds.extent().x * in.scene_bounds.extent().y * in.scene_bounds.extent().z;
        if (volume < 1e-9 * scale) {  // (near-)empty: both must say so or agree on a sliver
            EXPECT_LE(fast.body.volume(), 1e-6 * scale) << "configuration " << i;
            continue;
        }
        ++compared;
        EXPECT_NEAR(fast.body.volume(), volume, 1e-4 * volume) << "configuration " << i;
        EXPECT_TRUE(is_closed(fast.body)) << "configuration " << i;
    }
    EXPECT_GT(compared, 200);
}
