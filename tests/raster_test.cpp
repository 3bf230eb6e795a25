// The CPU depth rasterizer and the shadow lookup: coverage, fill rule, depth, clipping at w = 0.
#include <algorithm>
#include <cmath>
#include <random>
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "maps/map_lookup.hpp"
#include "raster/depth_map.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kResolution = 64;

// Light from above: u = x / 8 + 1/2, v = z / 8 + 1/2, d = (5 - y) / 10, so z_bias_scale = 1/10.
// A setup of one map, as most methods give.
ShadowSetup one_map(const ShadowMap& map) { return ShadowSetup{.maps = {map}}; }

ShadowMap overhead_map() {
    ShadowMap map;
    map.world_to_uvz = glm::transpose(glm::dmat4(0.125, 0.0, 0.0, 0.5,  //
                                                 0.0, 0.0, 0.125, 0.5,  //
                                                 0.0, -0.1, 0.0, 0.5,   //
                                                 0.0, 0.0, 0.0, 1.0));
    map.z_bias_scale = 0.1;
    return map;
}

double overhead_depth(double y) { return (5.0 - y) / 10.0; }

// World x (or z) of u (or v) under overhead_map().
double world_of(double t) { return (t - 0.5) * 8.0; }
double texel_centre(int i) { return (i + 0.5) / kResolution; }

// A spot-light style map: the light at the origin looking down -z, 90 degrees, near 0.1, far 10,
// clip space mapped to [0,1].
ShadowMap spot_map() {
    const glm::dmat4 to_unit = glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.5)), glm::dvec3(0.5));
    ShadowMap map;
    map.world_to_uvz = to_unit * glm::perspective(glm::radians(90.0), 1.0, 0.1, 10.0);
    return map;
}

// Appends the quad a, b, c, d (two triangles sharing the diagonal a-c) as object `object`.
void add_quad(WorldTriangles& out, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d,
              int object = 0) {
    const int base = static_cast<int>(out.vertices.size());
    out.vertices.insert(out.vertices.end(), {a, b, c, d});
    out.triangles.insert(out.triangles.end(), {{base, base + 1, base + 2}, {base, base + 2, base + 3}});
    out.object.insert(out.object.end(), {object, object});
}

// A horizontal square [x0, x1] x [z0, z1] at height y.
WorldTriangles square(double x0, double x1, double z0, double z1, double y) {
    WorldTriangles out;
    add_quad(out, {x0, y, z0}, {x0, y, z1}, {x1, y, z1}, {x1, y, z0});
    return out;
}

bool covered(const DepthMap& map, int x, int y) { return map.at(x, y) < 1.0f; }

int covered_count(const DepthMap& map) {
    int count = 0;
    for (int y = 0; y < map.resolution; ++y)
        for (int x = 0; x < map.resolution; ++x) count += covered(map, x, y);
    return count;
}

// Where the ray from the origin along `direction` meets triangle a, b, c: t and the barycentrics.
struct RayHit {
    double t;
    glm::dvec3 weights;
};

RayHit intersect(const glm::dvec3& direction, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    // Solve t * direction = a + s (b - a) + r (c - a) by Cramer's rule.
    const glm::dmat3 m(direction, a - b, a - c);
    const glm::dvec3 tsr = glm::inverse(m) * a;
    return {tsr.x, {1.0 - tsr.y - tsr.z, tsr.y, tsr.z}};
}

}  // namespace

TEST(RasterOrthographic, SquareCoversExactlyTheTexelsWhoseCentresItContains) {
    const double x0 = -1.3, x1 = 1.1, z0 = -0.7, z1 = 2.1;  // edges 21.6, 40.8, 26.4, 48.8 texels: off centres
    const DepthMap map = rasterize_depth(square(x0, x1, z0, z1, 1.0), {true}, one_map(overhead_map()), kResolution);
    ASSERT_EQ(map.depth.size(), static_cast<std::size_t>(kResolution * kResolution));
    for (int y = 0; y < kResolution; ++y)
        for (int x = 0; x < kResolution; ++x) {
            const double wx = world_of(texel_centre(x)), wz = world_of(texel_centre(y));
            EXPECT_EQ(covered(map, x, y), wx > x0 && wx < x1 && wz > z0 && wz < z1) << x << ", " << y;
        }
    EXPECT_EQ(covered_count(map), 19 * 23);  // centres 22.5 .. 40.5 by 26.5 .. 48.5
}

TEST(RasterOrthographic, CentresOnEdgesFollowTheTopLeftRule) {
    // Edges through the centres 16.5 and 32.5 (in texels) on both axes; the diagonal shared by the
    // two triangles passes through the centres (k + 0.5, k + 0.5).
    const double lo = world_of(16.5 / kResolution), hi = world_of(32.5 / kResolution);
    const DepthMap map = rasterize_depth(square(lo, hi, lo, hi, 1.0), {true}, one_map(overhead_map()), kResolution);
    // The low-u edge and the high-v edge own their centres; the other two do not.
    for (int y = 0; y < kResolution; ++y)
        for (int x = 0; x < kResolution; ++x)
            EXPECT_EQ(covered(map, x, y), x >= 16 && x <= 31 && y >= 17 && y <= 32) << x << ", " << y;
    EXPECT_EQ(covered_count(map), 16 * 16);  // neither a gap nor a spill along the diagonal
}

TEST(RasterOrthographic, EdgesSharedThroughTexelCentresLeaveNoGap) {
    // u = x / 64 and v = z / 64, so texel coordinates are world x and z exactly.
    ShadowMap map;
    map.world_to_uvz = glm::transpose(glm::dmat4(1.0 / 64, 0.0, 0.0, 0.0,  //
                                                 0.0, 0.0, 1.0 / 64, 0.0,  //
                                                 0.0, 0.0, 0.0, 0.5,       //
                                                 0.0, 0.0, 0.0, 1.0));
    // Diamonds split along a random diagonal through the centre (32.5, 32.5): rounding puts the
    // centre a hair to either side of the diagonal, yet one of the two triangles must take it.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> angle(0.0, 6.283), reach(0.1, 3.0);
    const glm::dvec2 centre(32.5, 32.5);
    for (int trial = 0; trial < 2000; ++trial) {
        const double t = angle(rng);
        const glm::dvec2 along(std::cos(t), std::sin(t)), across(-along.y, along.x);
        const glm::dvec2 a = centre - reach(rng) * along, b = centre + reach(rng) * along;
        const glm::dvec2 left = centre + 4.0 * across, right = centre - 4.0 * across;
        const auto world = [](const glm::dvec2& p) { return glm::dvec3(p.x, 0.0, p.y); };
        WorldTriangles diamond;
        add_quad(diamond, world(a), world(left), world(b), world(right));
        ASSERT_TRUE(covered(rasterize_depth(diamond, {true}, one_map(map), kResolution), 32, 32)) << "trial " << trial;
    }
}

TEST(RasterOrthographic, StoredDepthIsTheAnalyticDepthAtTexelCentres) {
    // A tilted square: y = 1 + 0.3 x + 0.2 z over [-2, 2]^2.
    const auto height = [](double x, double z) { return 1.0 + 0.3 * x + 0.2 * z; };
    WorldTriangles tilted;
    add_quad(tilted, {-2, height(-2, -2), -2}, {-2, height(-2, 2), 2}, {2, height(2, 2), 2}, {2, height(2, -2), -2});
    const DepthMap map = rasterize_depth(tilted, {true}, one_map(overhead_map()), kResolution);
    int checked = 0;
    for (int y = 0; y < kResolution; ++y)
        for (int x = 0; x < kResolution; ++x) {
            if (!covered(map, x, y)) continue;
            const double wx = world_of(texel_centre(x)), wz = world_of(texel_centre(y));
            EXPECT_NEAR(map.at(x, y), overhead_depth(height(wx, wz)), 1e-6) << x << ", " << y;
            ++checked;
        }
    EXPECT_EQ(checked, 32 * 32);
}

TEST(RasterOrthographic, KeepsTheNearestCasterAndSkipsNonCasters) {
    WorldTriangles scene;
    add_quad(scene, {-2, 1, -2}, {-2, 1, 2}, {2, 1, 2}, {2, 1, -2}, 0);                  // low caster
    add_quad(scene, {-1, 3, -1}, {-1, 3, 1}, {1, 3, 1}, {1, 3, -1}, 1);                  // high caster
    add_quad(scene, {-3, 4, -3}, {-3, 4, 3}, {3, 4, 3}, {3, 4, -3}, 2);                  // above all, casts not
    add_quad(scene, {-1.5, 2, -1.5}, {-1.5, 2, 1.5}, {1.5, 2, 1.5}, {1.5, 2, -1.5}, 3);  // middle, drawn last
    const DepthMap map = rasterize_depth(scene, {true, true, false, true}, one_map(overhead_map()), kResolution);
    const int row = kResolution / 2;  // z = 0.06; the columns below are at x = 0.06, 1.31, 1.81, 2.94
    EXPECT_NEAR(map.at(32, row), overhead_depth(3.0), 1e-7);
    EXPECT_NEAR(map.at(42, row), overhead_depth(2.0), 1e-7);
    EXPECT_NEAR(map.at(46, row), overhead_depth(1.0), 1e-7);
    EXPECT_EQ(map.at(55, row), 1.0f);  // only the non-caster is there
}

TEST(RasterPerspective, TriangleStraddlingTheLightIsDrawnOnlyWhereWIsPositive) {
    // a and b lie in front of the light, c behind it (w = -1). Divided by its negative w, c would
    // land at (0.75, 0.25), and an unclipped rasterizer would fill texels with v < 0.5, where no
    // point of the triangle in front of the light (y >= 0 there) can project.
    const glm::dvec3 a(0.0, 0.0, -2.0), b(1.0, 0.0, -2.0), c(-0.5, 0.5, 1.0);
    const ShadowMap map = spot_map();
    WorldTriangles triangle{{a, b, c}, {{0, 1, 2}}, {0}};
    const DepthMap depth = rasterize_depth(triangle, {true}, one_map(map), kResolution);

    int inside = 0;
    for (int y = 0; y < kResolution; ++y)
        for (int x = 0; x < kResolution; ++x) {
            const float stored = depth.at(x, y);
            ASSERT_TRUE(std::isfinite(stored) && stored >= 0.0f && stored <= 1.0f) << x << ", " << y;
            if (y < kResolution / 2) {
                EXPECT_FALSE(covered(depth, x, y)) << x << ", " << y;
                continue;
            }
            // The ray from the light through the texel centre (tan 45 degrees = 1).
            const glm::dvec3 direction(2.0 * texel_centre(x) - 1.0, 2.0 * texel_centre(y) - 1.0, -1.0);
            const RayHit hit = intersect(direction, a, b, c);
            const double margin = std::min({hit.weights.x, hit.weights.y, hit.weights.z});
            const bool clearly_in = hit.t > 0.0 && margin > 1e-6, clearly_out = hit.t <= 0.0 || margin < -1e-6;
            EXPECT_FALSE(clearly_out && covered(depth, x, y)) << x << ", " << y;
            if (!clearly_in) continue;
            ++inside;
            ASSERT_TRUE(covered(depth, x, y)) << x << ", " << y;
            const double expected = world_to_uvz(map, hit.t * direction).z;
            EXPECT_NEAR(stored, std::clamp(expected, 0.0, 1.0), 1e-5) << x << ", " << y;
        }
    EXPECT_GT(inside, 100);
}

TEST(RasterLookup, ShadowedUnderTheCasterLitBesideItAndTheBiasMovesTheDecision) {
    const ShadowMap map = overhead_map();
    const DepthMap depth = rasterize_depth(square(-1, 1, -1, 1, 1.0), {true}, one_map(map), kResolution);
    const glm::dvec3 under(0.1, 0.95, 0.2);  // 0.05 below the caster
    EXPECT_TRUE(in_shadow(depth, one_map(map), under, 0.0));
    EXPECT_TRUE(in_shadow(depth, one_map(map), under, 0.04));
    EXPECT_FALSE(in_shadow(depth, one_map(map), under, 0.06));
    EXPECT_FALSE(in_shadow(depth, one_map(map), {3.0, 0.0, 0.2}, 0.0));  // beside it
    EXPECT_FALSE(in_shadow(depth, one_map(map), {0.1, 1.5, 0.2}, 0.0));  // above it
}

TEST(RasterLookup, PointsOffTheMapAreLit) {
    // Every texel holds depth 0: any point the lookup places on the map is shadowed.
    const DepthMap full{kResolution, std::vector<float>(kResolution * kResolution, 0.0f)};
    const ShadowMap spot = spot_map();
    EXPECT_TRUE(in_shadow(full, one_map(spot), {0.0, 0.0, -2.0}, 0.0));
    EXPECT_FALSE(in_shadow(full, one_map(spot), {-0.5, 0.5, 1.0}, 0.0));  // behind the light: w < 0, u, v inside
    EXPECT_FALSE(in_shadow(full, one_map(spot), {3.0, 0.0, -2.0}, 0.0));  // u > 1
    const ShadowMap overhead = overhead_map();
    EXPECT_FALSE(in_shadow(full, one_map(overhead), {0.0, 0.0, -4.5}, 0.0));  // v < 0
    EXPECT_TRUE(in_shadow(full, one_map(overhead), {4.0, 0.0, 4.0}, 0.0));    // u = v = 1: the last texel
}
