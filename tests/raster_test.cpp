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

// Texel coordinates are world x and z exactly (u = x / 64, v = z / 64), and d = 0.5 + y / 10.
ShadowMap texel_space_map() {
    ShadowMap map;
    map.world_to_uvz = glm::transpose(glm::dmat4(1.0 / kResolution, 0.0, 0.0, 0.0,  //
                                                 0.0, 0.0, 1.0 / kResolution, 0.0,  //
                                                 0.0, 0.1, 0.0, 0.5,                //
                                                 0.0, 0.0, 0.0, 1.0));
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
    ASSERT_EQ(map.codes.size(), static_cast<std::size_t>(kResolution * kResolution));
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
    const ShadowMap map = texel_space_map();
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

TEST(RasterOrthographic, NoCasterLeavesEveryTexelEmpty) {
    const DepthMap map = rasterize_depth(square(-2, 2, -2, 2, 1.0), {false}, one_map(overhead_map()), kResolution);
    EXPECT_EQ(covered_count(map), 0);
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
    DepthMap full(kResolution, {});
    for (int y = 0; y < kResolution; ++y)
        for (int x = 0; x < kResolution; ++x) full.set(x, y, 0.0);
    const ShadowMap spot = spot_map();
    EXPECT_TRUE(in_shadow(full, one_map(spot), {0.0, 0.0, -2.0}, 0.0));
    EXPECT_FALSE(in_shadow(full, one_map(spot), {-0.5, 0.5, 1.0}, 0.0));  // behind the light: w < 0, u, v inside
    EXPECT_FALSE(in_shadow(full, one_map(spot), {3.0, 0.0, -2.0}, 0.0));  // u > 1
    const ShadowMap overhead = overhead_map();
    EXPECT_FALSE(in_shadow(full, one_map(overhead), {0.0, 0.0, -4.5}, 0.0));  // v < 0
    EXPECT_TRUE(in_shadow(full, one_map(overhead), {4.0, 0.0, 4.0}, 0.0));    // u = v = 1: the last texel
}

// ---- The fast rasterizer against a straightforward one ----

namespace {

// The edge function of a -> b at p, evaluated from the lexicographically smaller end, and the
// top-left rule: what the header promises, written texel by texel.
double edge_value(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
    if (b.x < a.x || (b.x == a.x && b.y < a.y)) return -edge_value(b, a, p);
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

bool holds(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
    const double e = edge_value(a, b, p);
    return e > 0.0 || (e == 0.0 && (b.y < a.y || (b.y == a.y && b.x < a.x)));
}

// Every texel centre of the map's tile tested against every triangle (each wholly in front of the
// map, w > 0, so that nothing but the tile clips it), depth by barycentric weights, the least kept.
DepthMap brute_force_depth(const WorldTriangles& triangles, const ShadowMap& map, int resolution) {
    DepthMap out(resolution, {});
    const glm::ivec2 first = texel_of(map, glm::dvec2(0.0), resolution),
                     last = texel_of(map, glm::dvec2(1.0), resolution);
    for (const std::array<int, 3>& corners : triangles.triangles) {
        std::array<glm::dvec2, 3> p;
        std::array<double, 3> depth;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 uvz = world_to_uvz(map, triangles.vertices[corners[k]]);
            p[k] = texture_uv(map, glm::dvec2(uvz)) * static_cast<double>(resolution);
            depth[k] = uvz.z;
        }
        double area = edge_value(p[0], p[1], p[2]);
        if (area == 0.0) continue;
        if (area < 0.0) {  // make it counter-clockwise
            std::swap(p[1], p[2]);
            std::swap(depth[1], depth[2]);
            area = -area;
        }
        for (int y = first.y; y <= last.y; ++y)
            for (int x = first.x; x <= last.x; ++x) {
                const glm::dvec2 centre(x + 0.5, y + 0.5);
                if (!holds(p[1], p[2], centre) || !holds(p[2], p[0], centre) || !holds(p[0], p[1], centre)) continue;
                const double d =
                    (edge_value(p[1], p[2], centre) * depth[0] + edge_value(p[2], p[0], centre) * depth[1] +
                     edge_value(p[0], p[1], centre) * depth[2]) /
                    area;
                out.set(x, y, std::min(out.at(x, y), std::max(0.0, d)));
            }
    }
    return out;
}

// The same texels covered, and the same depths but for the float rounding of the interpolation.
void expect_same_map(const DepthMap& actual, const DepthMap& expected) {
    ASSERT_EQ(actual.codes.size(), expected.codes.size());
    for (int y = 0; y < actual.resolution; ++y)
        for (int x = 0; x < actual.resolution; ++x) {
            ASSERT_EQ(covered(actual, x, y), covered(expected, x, y)) << x << ", " << y;
            ASSERT_NEAR(actual.at(x, y), expected.at(x, y), 2e-7) << x << ", " << y;
        }
}

void add_triangle(WorldTriangles& out, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const int base = static_cast<int>(out.vertices.size());
    out.vertices.insert(out.vertices.end(), {a, b, c});
    out.triangles.push_back({base, base + 1, base + 2});
    out.object.push_back(0);
}

// Triangles of every size from a fraction of a texel to the whole map, slivers among them, both
// windings, at random heights, under texel_space_map(): `place` gives a vertex's texel coordinate.
template <class Place>
WorldTriangles random_triangles(int count, unsigned seed, Place&& place) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    WorldTriangles out;
    for (int i = 0; i < count; ++i) {
        const glm::dvec2 centre(kResolution * unit(rng), kResolution * unit(rng));
        const double size = 0.3 * std::pow(200.0, unit(rng));  // 0.3 .. 60 texels
        std::array<glm::dvec3, 3> corner;
        for (glm::dvec3& c : corner) {
            const glm::dvec2 p = place(centre + size * glm::dvec2(unit(rng) - 0.5, unit(rng) - 0.5));
            c = {p.x, 4.0 * unit(rng) - 2.0, p.y};
        }
        if (i % 5 == 0) corner[2] = glm::mix(corner[0], corner[1], unit(rng)) + glm::dvec3(0.01, 0.0, 0.0);  // a sliver
        add_triangle(out, corner[0], corner[1], corner[2]);
    }
    return out;
}

}  // namespace

TEST(RasterAgreement, GridAlignedTrianglesMatchATexelByTexelReference) {
    // Vertices on the half-texel grid inside the map: texel centres fall on edges and vertices
    // everywhere, so each row's run ends are settled exactly at ties.
    const auto on_grid = [](const glm::dvec2& p) {
        return glm::clamp(glm::round(2.0 * p) / 2.0, glm::dvec2(0.0), glm::dvec2(kResolution));
    };
    const WorldTriangles triangles = random_triangles(300, 11, on_grid);
    const ShadowMap map = texel_space_map();
    expect_same_map(rasterize_depth(triangles, {true}, one_map(map), kResolution),
                    brute_force_depth(triangles, map, kResolution));
}

TEST(RasterAgreement, TrianglesCutByTheTileMatchTheReferenceInsideIt) {
    // Off-grid vertices over twice the map, in a perspective map's tile: most triangles reach past
    // the tile's edges and are clipped there (new edges along the tile's border, between centres).
    ShadowMap map = spot_map();
    map.viewport = {0.25, 0.5, 0.75, 1.0};
    const auto in_front = [](const glm::dvec2& p) { return 3.0 * p - glm::dvec2(kResolution); };
    WorldTriangles triangles = random_triangles(300, 12, in_front);
    for (glm::dvec3& v : triangles.vertices)  // texel-space x, z to the light's view, 1.5 .. 2.5 in front of it
        v = glm::dvec3(v.x / kResolution - 0.5, v.z / kResolution - 0.5, -1.0) * (2.0 + 0.25 * v.y);
    expect_same_map(rasterize_depth(triangles, {true}, one_map(map), kResolution),
                    brute_force_depth(triangles, map, kResolution));
}

TEST(RasterSharedEdges, EachCentreOnASharedDiagonalTakesItsOwnersDepthAlone) {
    // A square split along its diagonal, which runs through the centres (k + 0.5, k + 0.5): the lower
    // triangle's diagonal runs toward lower v (counter-clockwise), so it owns them, whether it lies
    // nearer or farther than the upper one; a centre drawn by both would take the nearer depth.
    for (const auto& [lower_y, upper_y] : {std::pair{1.0, -1.0}, std::pair{-1.0, 1.0}}) {
        WorldTriangles quad;
        add_triangle(quad, {8, lower_y, 8}, {40, lower_y, 8}, {40, lower_y, 40});
        add_triangle(quad, {8, upper_y, 8}, {40, upper_y, 40}, {8, upper_y, 40});
        const DepthMap map = rasterize_depth(quad, {true}, one_map(texel_space_map()), kResolution);
        const float lower = 0.5f + 0.1f * static_cast<float>(lower_y),
                    upper = 0.5f + 0.1f * static_cast<float>(upper_y);
        for (int y = 8; y < 40; ++y)
            for (int x = 8; x < 40; ++x) ASSERT_FLOAT_EQ(map.at(x, y), y <= x ? lower : upper) << x << ", " << y;
    }
}

TEST(RasterInvariance, MovingTheSceneFarAndScalingItWithItsMapChangesNothing) {
    // The map follows the scene: world' = scale * world + offset, world_to_uvz' = world_to_uvz * world_from_world'.
    const auto anywhere = [](const glm::dvec2& p) { return p; };
    const WorldTriangles near = random_triangles(200, 13, anywhere);
    const glm::dvec3 offset(3.0e5, -2.0e5, 7.0e5);
    const double scale = 1000.0;
    WorldTriangles far = near;
    for (glm::dvec3& v : far.vertices) v = scale * v + offset;
    ShadowMap moved = texel_space_map();
    moved.world_to_uvz = moved.world_to_uvz * glm::scale(glm::dmat4(1.0), glm::dvec3(1.0 / scale)) *
                         glm::translate(glm::dmat4(1.0), -offset);
    expect_same_map(rasterize_depth(far, {true}, one_map(moved), kResolution),
                    rasterize_depth(near, {true}, one_map(texel_space_map()), kResolution));
}
