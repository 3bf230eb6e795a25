// A paraboloid map's tessellation error (raster/paraboloid_edges): the closed forms of issue 14, the
// sagitta against the projected edge sampled finely, the splitting's guarantees, and what splitting
// buys against the exact depth picture traced texel by texel (reference/traced_depth_map).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <tuple>
#include <utility>

#include "maps/map_lookup.hpp"
#include "raster/depth_map.hpp"
#include "raster/paraboloid_edges.hpp"
#include "reference/traced_depth_map.hpp"
#include "scene/scene.hpp"
#include "sampled_bow.hpp"

using namespace shadowlab;

namespace {

const double kRoot2 = std::sqrt(2.0);
const Paraboloid kAtOrigin{.centre = glm::dvec3(0.0), .frame_from_world = glm::dmat3(1.0), .near = 0.1, .far = 10.0};

// The point at fraction t along a–b, seen by the paraboloid: its disc coordinates.
glm::dvec2 image_at(const Paraboloid& p, const glm::dvec3& a, const glm::dvec3& b, double t) {
    return disc_of(glm::normalize(p.frame_from_world * (glm::mix(a, b, t) - p.centre)));
}

// The greatest distance of the projected edge's points from its chord, over `samples` + 1 points.
double sampled_sagitta(const Paraboloid& p, const glm::dvec3& a, const glm::dvec3& b, int samples) {
    return shadowlab::testing::sampled_bow([&](double t) { return image_at(p, a, b, t); }, samples);
}

}  // namespace

// (1, 0, 1)/√2, 45° off the axis, lands at tan(22.5°) = √2 - 1 on the disc; the back hemisphere (its
// frame half a turn about x) takes (1, 0, -1)/√2 to the same place. The inverse mapping undoes it.
TEST(ParaboloidDisc, ClosedFormBothHemispheres) {
    const glm::dvec3 front = glm::dvec3(1, 0, 1) / kRoot2, back = glm::dvec3(1, 0, -1) / kRoot2;
    const glm::dvec2 at = disc_of(front);
    EXPECT_NEAR(at.x, 0.41421, 1e-5);
    EXPECT_NEAR(at.y, 0.0, 1e-12);
    ShadowMap map{.projection = Projection::paraboloid};
    map.paraboloid.frame_from_world = glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, -1));
    const glm::dvec3 uvz = world_to_uvz(map, back);
    EXPECT_NEAR(2.0 * uvz.x - 1.0, 0.41421, 1e-5);
    EXPECT_NEAR(2.0 * uvz.y - 1.0, 0.0, 1e-12);
    for (const glm::dvec3& d : {front, glm::normalize(glm::dvec3(-0.3, 0.8, 0.1)), glm::dvec3(0, 0, 1)}) {
        const glm::dvec3 again = direction_of(disc_of(d));
        EXPECT_NEAR(glm::distance(again, d), 0.0, 1e-14);
    }
}

// The issue's edge from (1, 0, 1)/√2 to (0, 1, 1)/√2. Its image is symmetric about the diagonal, so
// the image of the edge's midpoint, (1, 1, 2)/√6 -> (0.2247, 0.2247), is the arc's farthest point from
// the chord, whose midpoint is (0.2071, 0.2071): a sagitta of 0.02494 disc units, 12.8 texels at 1024
// texels per hemisphere diameter (512 per disc unit). Half the edge bows about a quarter as much.
TEST(EdgeSagitta, IssueClosedForms) {
    const glm::dvec3 a = glm::dvec3(1, 0, 1) / kRoot2, b = glm::dvec3(0, 1, 1) / kRoot2;
    const glm::dvec2 from = disc_of(a), to = disc_of(b);
    EXPECT_NEAR(from.x, 0.4142, 1e-4);
    EXPECT_NEAR(to.y, 0.4142, 1e-4);
    const glm::dvec2 true_midpoint = image_at(kAtOrigin, a, b, 0.5), chord_midpoint = (from + to) / 2.0;
    EXPECT_NEAR(true_midpoint.x, 0.2247, 1e-4);
    EXPECT_NEAR(true_midpoint.y, 0.2247, 1e-4);
    EXPECT_NEAR(chord_midpoint.x, 0.2071, 1e-4);
    const double sagitta = edge_sagitta(kAtOrigin, a, b);
    EXPECT_NEAR(sagitta, 0.02494, 1e-5);
    EXPECT_NEAR(sagitta, glm::distance(true_midpoint, chord_midpoint), 1e-12) << "the farthest point, by symmetry";
    ShadowMap map{.projection = Projection::paraboloid, .paraboloid = kAtOrigin};
    EXPECT_NEAR(sagitta * texels_per_disc_unit(map, 1024), 12.8, 0.05);
    const double halved = edge_sagitta(kAtOrigin, a, (a + b) / 2.0);
    EXPECT_NEAR(sagitta / halved, 4.0, 0.25);
}

// The closed form against the projected edge sampled finely, both ways round to the last bit, for
// edges that are not symmetric: there the image of the edge's midpoint is not the farthest point.
TEST(EdgeSagitta, ClosedFormMatchesTheSampledCurve) {
    const Paraboloid turned{
        .centre = {1, 2, 3},
        .frame_from_world = glm::dmat3(glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0))};
    const std::pair<glm::dvec3, glm::dvec3> edges[] = {
        {{1, 0, 1}, {0, 1, 3}}, {{-2, 1, 0.5}, {3, -1, 2}}, {{0.1, 0.1, 5}, {4, -3, 0.2}}, {{-1, -1, 1}, {1, 1, 1}}};
    for (const auto& [a, b] : edges) {
        const double sagitta = edge_sagitta(kAtOrigin, a, b);
        EXPECT_NEAR(sagitta, sampled_sagitta(kAtOrigin, a, b, 20000), 1e-8 + 1e-6 * sagitta) << a.x << " " << b.x;
        EXPECT_EQ(sagitta, edge_sagitta(kAtOrigin, b, a));
        // The same edge seen by a moved and turned map: the frame's side, the centre's offset.
        const glm::dvec3 moved_a = turned.centre + glm::transpose(turned.frame_from_world) * a;
        const glm::dvec3 moved_b = turned.centre + glm::transpose(turned.frame_from_world) * b;
        EXPECT_NEAR(edge_sagitta(turned, moved_a, moved_b), sagitta, 1e-12);
    }
    const glm::dvec3 a(1, 0, 1), b(0, 1, 3);
    const glm::dvec2 from = image_at(kAtOrigin, a, b, 0.0), to = image_at(kAtOrigin, a, b, 1.0);
    const glm::dvec2 across = glm::normalize(glm::dvec2(from.y - to.y, to.x - from.x));
    const double midpoint_offset = std::abs(glm::dot(image_at(kAtOrigin, a, b, 0.5) - from, across));
    EXPECT_LT(midpoint_offset, 0.99 * edge_sagitta(kAtOrigin, a, b));
}

// Behind the plane nothing is drawn; across it the bound stays finite short of the singular point and
// shrinks as the crossing piece does.
TEST(EdgeSagitta, EdgesAcrossThePlane) {
    EXPECT_EQ(edge_sagitta(kAtOrigin, {1, 0, -1}, {0, 1, -2}), 0.0);
    const glm::dvec3 front(1, 0, 0.5), back(0.2, 1, -3);
    const double whole = edge_sagitta(kAtOrigin, front, back);
    EXPECT_TRUE(std::isfinite(whole));
    const glm::dvec3 near_plane_front = glm::mix(front, back, 0.12), near_plane_back = glm::mix(front, back, 0.16);
    EXPECT_LT(edge_sagitta(kAtOrigin, near_plane_front, near_plane_back), whole / 16.0);
    EXPECT_FALSE(edge_sagitta(kAtOrigin, front, {0, 0, -2}) < 1e3) << "toward the singular point the chord runs off";
}

// Solid angle per unit of disc area: |∂d/∂x × ∂d/∂y| of the inverse mapping, taken numerically, is
// 4 / (1 + ρ²)²: 4 at the centre, 1 on the rim, so a rim texel sees a quarter of a centre texel's angle.
TEST(ParaboloidDisc, SolidAnglePerTexel) {
    constexpr double h = 1e-6;
    for (const double rho : {0.0, 0.3, 0.6, 0.9, 1.0})
        for (const double angle : {0.0, 1.0, 2.5}) {
            const glm::dvec2 at = rho * glm::dvec2(std::cos(angle), std::sin(angle));
            const glm::dvec3 dx = (direction_of(at + glm::dvec2(h, 0)) - direction_of(at - glm::dvec2(h, 0))) / (2 * h);
            const glm::dvec3 dy = (direction_of(at + glm::dvec2(0, h)) - direction_of(at - glm::dvec2(0, h))) / (2 * h);
            const double solid_angle = glm::length(glm::cross(dx, dy));
            EXPECT_NEAR(solid_angle, 4.0 / std::pow(1.0 + rho * rho, 2), 1e-6) << rho;
            if (rho == 0.0) {
                EXPECT_NEAR(solid_angle, 4.0, 1e-6);
            } else if (rho == 1.0) {
                EXPECT_NEAR(solid_angle, 1.0, 1e-6);
            }
        }
}

namespace {

SceneObject box(const glm::dvec3& position, const glm::dvec3& size, double yaw_deg = 0.0) {
    SceneObject object;
    object.position = position;
    object.size = size;
    object.rotation_deg = {0.0, yaw_deg, 0.0};
    return object;
}

struct Lexicographic {
    bool operator()(const glm::dvec3& a, const glm::dvec3& b) const {
        return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    }
    bool operator()(const std::pair<glm::dvec3, glm::dvec3>& a, const std::pair<glm::dvec3, glm::dvec3>& b) const {
        return (*this)(a.first, b.first) || (!(*this)(b.first, a.first) && (*this)(a.second, b.second));
    }
};

// Triangles per undirected edge, by vertex index.
std::map<std::pair<int, int>, int> edge_uses(const WorldTriangles& mesh) {
    std::map<std::pair<int, int>, int> uses;
    for (const std::array<int, 3>& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
    return uses;
}

double area(const WorldTriangles& mesh, int object) {
    double sum = 0.0;
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        if (mesh.object[i] != object) continue;
        const std::array<int, 3>& t = mesh.triangles[i];
        const glm::dvec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
        sum += glm::length(glm::cross(b - a, c - a)) / 2.0;
    }
    return sum;
}

// A point light 2 above the ground at the origin, looking down (the hemisphere's +z is world -y):
// a long low slab right under it, a turned one beside it, a post rising through the light's
// horizontal plane, all closed boxes.
Scene light_over_boxes() {
    Scene scene;
    scene.objects = {box({0, 0.4, 0.3}, {9, 0.8, 2.5}), box({1.5, 0.3, -2.5}, {5, 0.6, 1.2}, 35.0),
                     box({-2.5, 1.5, -1.5}, {0.6, 3.0, 0.6})};
    return scene;
}

const Paraboloid kDownFromTwo{
    .centre = {0, 2, 0},
    .frame_from_world = glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0)),
    .near = 0.1,
    .far = 6.0};

}  // namespace

// After splitting to half a texel at 1024 texels across the hemisphere, no edge bows more than half a
// texel; every edge of the closed boxes is still shared by exactly two triangles, each piece keeps its
// box and winding, the pieces cover the boxes' surfaces exactly, and an edge's pieces are those
// split_edge gives.
TEST(SplitForParaboloid, EveryEdgeUnderTheTargetAndWatertight) {
    const Scene scene = light_over_boxes();
    const WorldTriangles input = tessellate(scene);
    for (const auto& [edge, uses] : edge_uses(input)) ASSERT_EQ(uses, 2) << "the input boxes are closed";
    constexpr double texels_per_unit = 512.0, target = 0.5;
    constexpr int resolution = 1024;  // the tile the whole texture
    const ShadowMap map{.projection = Projection::paraboloid, .paraboloid = kDownFromTwo, .max_sagitta_texels = target};
    ASSERT_EQ(texels_per_disc_unit(map, resolution), texels_per_unit);
    const WorldTriangles split = split_casters(input, std::vector<bool>(scene.objects.size(), true), map, resolution);
    std::printf("split: %zu triangles -> %zu\n", input.triangles.size(), split.triangles.size());
    EXPECT_GT(split.triangles.size(), 20 * input.triangles.size());
    double worst = 0.0;
    for (const auto& [edge, uses] : edge_uses(split)) {
        EXPECT_EQ(uses, 2) << "a crack at " << edge.first << "-" << edge.second;
        worst = std::max(worst, edge_sagitta(kDownFromTwo, split.vertices[edge.first], split.vertices[edge.second]));
    }
    std::printf("worst sagitta after splitting: %.3f texels\n", worst * texels_per_unit);
    EXPECT_LE(worst * texels_per_unit, target);
    for (int object = 0; object < int(scene.objects.size()); ++object)
        EXPECT_NEAR(area(split, object), area(input, object), 1e-9 * area(input, object));
    std::set<std::pair<glm::dvec3, glm::dvec3>, Lexicographic> split_edges;  // by their ends' positions
    for (const auto& [edge, uses] : edge_uses(split))
        split_edges.insert(std::minmax(split.vertices[edge.first], split.vertices[edge.second], Lexicographic{}));
    for (const auto& [edge, uses] : edge_uses(input)) {  // split_edge gives the pieces the mesh holds
        const std::vector<glm::dvec3> points =
            split_edge(map, input.vertices[edge.first], input.vertices[edge.second], resolution);
        for (std::size_t k = 0; k + 1 < points.size(); ++k)
            EXPECT_TRUE(split_edges.count(std::minmax(points[k], points[k + 1], Lexicographic{}))) << k;
    }
    for (std::size_t i = 0; i < split.triangles.size(); ++i) {  // winding: the normal points away from its box
        const std::array<int, 3>& t = split.triangles[i];
        const glm::dvec3 &a = split.vertices[t[0]], &b = split.vertices[t[1]], &c = split.vertices[t[2]];
        const glm::dvec3 outward = (a + b + c) / 3.0 - scene.objects[split.object[i]].position;
        ASSERT_GT(glm::dot(glm::cross(b - a, c - a), outward), 0.0) << i;
    }
}

// The depth picture the rasterizer draws (vertices projected, edges straight, depth interpolated
// linearly across the disc, as a GPU does) against the exact one traced texel by texel. Split to half
// a texel, the texels whose coverage is wrong (drawn where no caster is seen, or the reverse) fall to
// a small fraction; so do those whose depth is off by more than a hundredth of the range, since the
// distance to the light is not linear across the disc either and smaller triangles follow it closer.
TEST(SplitForParaboloid, RasterApproachesTheTracedDepth) {
    constexpr int resolution = 512;
    const Scene scene = light_over_boxes();
    const WorldTriangles triangles = tessellate(scene);
    const std::vector<bool> casts(scene.objects.size(), true);
    ShadowSetup setup{.maps = {ShadowMap{.projection = Projection::paraboloid, .paraboloid = kDownFromTwo}}};
    const DepthMap exact = traced_depth_map(triangles, casts, setup, resolution);
    struct Wrong {
        int coverage = 0, depth = 0;  // depth: among the texels both cover
    };
    const auto wrong_texels = [&](const DepthMap& drawn) {
        Wrong wrong;
        for (int y = 0; y < resolution; ++y)
            for (int x = 0; x < resolution; ++x) {
                const bool drawn_covers = drawn.at(x, y) < 1.0, exact_covers = exact.at(x, y) < 1.0;
                wrong.coverage += drawn_covers != exact_covers;
                wrong.depth += drawn_covers && exact_covers && std::abs(drawn.at(x, y) - exact.at(x, y)) > 0.01;
            }
        return wrong;
    };
    const Wrong straight = wrong_texels(rasterize_depth(triangles, casts, setup, resolution));
    setup.maps[0].max_sagitta_texels = 0.5;
    const auto start = std::chrono::steady_clock::now();
    const Wrong split = wrong_texels(rasterize_depth(triangles, casts, setup, resolution));
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "texels of %d² unlike the traced map, as given -> split to 0.5 texel: coverage %d -> %d (%.0fx fewer), "
        "depth off by > 0.01 %d -> %d; split and drawn in %.1f ms\n",
        resolution, straight.coverage, split.coverage, double(straight.coverage) / std::max(1, split.coverage),
        straight.depth, split.depth, ms);
    EXPECT_GT(straight.coverage, 1000) << "long edges seen from close by bow by many texels";
    EXPECT_LT(10 * split.coverage, straight.coverage);
    EXPECT_LT(2 * split.depth, straight.depth);
}
