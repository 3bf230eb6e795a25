// The ray tracer at the edges of its input: a ray Embree cannot take is refused by name
// (std::invalid_argument) instead of tripping Embree's assertion, and a direction of any finite
// size traces the same segment as its unit direction.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <gtest/gtest.h>

#include "reference/camera_rays.hpp"
#include "reference/exact_shadows.hpp"
#include "reference/ray_tracer.hpp"

namespace shadowlab {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// One casting triangle in the plane z = 0 around the origin; the rays start at z = 5.
class RayTracerInput : public testing::Test {
protected:
    const WorldTriangles triangle{{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}, {{0, 1, 2}}, {0}};
    const RayTracer tracer{triangle, {true}};
    const glm::dvec3 above{0, 0, 5}, down{0, 0, -1};
};

// Runs `trace`, expecting std::invalid_argument whose message contains `what`.
template <class Trace>
void expect_refused(Trace trace, const std::string& what) {
    try {
        trace();
        ADD_FAILURE() << "traced; expected a refusal naming " << what;
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find(what), std::string::npos) << error.what();
    }
}

TEST_F(RayTracerInput, AnOrdinaryRayMeetsTheTriangle) {
    EXPECT_TRUE(tracer.first_hit(above, down, 0.0, kInf).has_value());
    EXPECT_TRUE(tracer.blocked(above, down, kInf));
    EXPECT_FALSE(tracer.blocked(above, -down, kInf));
}

TEST_F(RayTracerInput, DirectionsOfAnyFiniteSizeTraceTheSameSegment) {
    for (double size : {1e-300, 1e-30, 1.0, 1e30, 1e300}) {
        EXPECT_TRUE(tracer.first_hit(above, size * down, 0.0, kInf).has_value()) << size;
        EXPECT_FALSE(tracer.first_hit(above, size * down, 6.0 / size, kInf).has_value()) << size;
        EXPECT_FALSE(tracer.blocked(above, size * down, 4.0 / size)) << size << ": ends above the triangle";
        EXPECT_TRUE(tracer.blocked(above, size * down, 6.0 / size)) << size << ": ends below it";
    }
}

TEST_F(RayTracerInput, AnOriginBeyondTheFloatRangeIsRefused) {
    expect_refused([&] { tracer.first_hit({1e30, 0, 0}, down, 0.0, kInf); }, "invalid ray: origin [1e+30, 0, 0]");
    expect_refused([&] { tracer.blocked({0, kNaN, 5}, down, kInf); }, "invalid ray: origin [0, nan, 5]");
    EXPECT_TRUE(tracer.blocked({0, 0, 1e17}, down, kInf)) << "far, but within Embree's range";
}

TEST_F(RayTracerInput, ANonFiniteOrZeroDirectionIsRefused) {
    expect_refused([&] { tracer.first_hit(above, {0, 0, -kInf}, 0.0, kInf); }, "direction [0, 0, -inf] is not finite");
    expect_refused([&] { tracer.blocked(above, {kNaN, 0, -1}, kInf); }, "direction [nan, 0, -1] is not finite");
    expect_refused([&] { tracer.blocked(above, {0, 0, 0}, kInf); }, "direction is zero");
}

TEST_F(RayTracerInput, ABadTRangeIsRefused) {
    expect_refused([&] { tracer.first_hit(above, down, kNaN, 10.0); }, "t range [nan, 10]");
    expect_refused([&] { tracer.first_hit(above, down, -1.0, 10.0); }, "t range [-1, 10]");
    expect_refused([&] { tracer.first_hit(above, down, 6.0, 4.0); }, "t range [6, 4]");
    expect_refused([&] { tracer.first_hit(above, down, kInf, kInf); }, "t range [inf, inf]");
    expect_refused([&] { tracer.blocked(above, down, kNaN); }, "t range [0, nan]");
}

// What the fuzzer found aborting: the widest field of view the loader accepts, at the widest
// aspect, gives camera rays with components near 1e19, beyond Embree's float range (1.8e18).
TEST(RayTracerScene, TheWidestViewIsTraced) {
    Scene scene;
    scene.objects.push_back(SceneObject{});
    scene.camera.fov_y_deg = std::nextafter(180.0, 0.0);
    scene.camera.aspect = 1e3;
    constexpr int kSide = 16;
    const glm::dvec3 corner_ray = CameraRays(scene.camera, kSide, kSide).ray(0, 0).direction;
    ASSERT_GT(std::max({std::abs(corner_ray.x), std::abs(corner_ray.y), std::abs(corner_ray.z)}), 1e18);
    EXPECT_NO_THROW(exact_reference(scene, tessellate(scene), kSide, kSide));
}

}  // namespace
}  // namespace shadowlab
