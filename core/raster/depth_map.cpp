// Triangles are clipped in homogeneous space, divided by w, and sampled at texel centres with edge
// functions; d / w is affine in (u / w, v / w), so screen-space interpolation of it is exact.
#include "raster/depth_map.hpp"

#include "geometry/homogeneous_clip.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace shadowlab {
namespace {

constexpr double kMinRelativeW = 1e-9;  // clipped w stays above this fraction of the triangle's largest |w|

using Polygon = HomogeneousPolygon;  // (u, v, d_pre, w)

// The part of a triangle with w > 0 and 0 <= u, v <= w: in front of the map's centre and on it.
// The w plane sits a hair above 0, relative to the triangle's scale, so the division stays finite.
Polygon clip_to_map(const std::array<glm::dvec4, 3>& triangle) {
    const double min_w = kMinRelativeW * std::max({std::abs(triangle[0].w), std::abs(triangle[1].w),
                                                   std::abs(triangle[2].w)});
    if (!(min_w > 0.0)) return {};
    const ClipPlane planes[] = {{{0, 0, 0, 1}, min_w}, {{1, 0, 0, 0}, 0.0}, {{-1, 0, 0, 1}, 0.0},
                                {{0, 1, 0, 0}, 0.0},   {{0, -1, 0, 1}, 0.0}};
    Polygon polygon(triangle.begin(), triangle.end());
    for (const ClipPlane& plane : planes) polygon = clip(polygon, plane);
    return polygon;
}

// A vertex after division: position in texels, depth in map units.
struct ScreenVertex {
    glm::dvec2 p;
    double depth;
};

ScreenVertex to_screen(const glm::dvec4& h, int resolution) {
    return {glm::dvec2(h.x, h.y) / h.w * static_cast<double>(resolution), h.z / h.w};
}

// Twice the signed area of (a, b, p): positive when p lies left of a -> b. Always evaluated from
// the lexicographically smaller endpoint, so that the two triangles sharing an edge get exactly
// opposite values and no texel centre on it is lost to rounding.
double edge(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
    if (b.x < a.x || (b.x == a.x && b.y < a.y)) return -edge(b, a, p);
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// The top-left rule: a centre exactly on an edge belongs to the one triangle (of the two sharing
// it, both counter-clockwise) along which the edge runs toward lower v, or along v toward lower u.
bool owns_edge(const glm::dvec2& a, const glm::dvec2& b) { return b.y < a.y || (b.y == a.y && b.x < a.x); }

bool inside(double e, const glm::dvec2& a, const glm::dvec2& b) { return e > 0.0 || (e == 0.0 && owns_edge(a, b)); }

// First and last texel whose centre (i + 0.5) lies in [lo, hi], within the map.
std::pair<int, int> texel_span(double lo, double hi, int resolution) {
    return {std::max(0, static_cast<int>(std::ceil(lo - 0.5))),
            std::min(resolution - 1, static_cast<int>(std::floor(hi - 0.5)))};
}

void draw_triangle(ScreenVertex a, ScreenVertex b, ScreenVertex c, DepthMap& map) {
    double area = edge(a.p, b.p, c.p);
    if (area == 0.0) return;
    if (area < 0.0) {  // both windings are drawn: make it counter-clockwise
        std::swap(b, c);
        area = -area;
    }
    const glm::dvec2 lo = glm::min(a.p, glm::min(b.p, c.p)), hi = glm::max(a.p, glm::max(b.p, c.p));
    const auto [x0, x1] = texel_span(lo.x, hi.x, map.resolution);
    const auto [y0, y1] = texel_span(lo.y, hi.y, map.resolution);
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const glm::dvec2 p(x + 0.5, y + 0.5);
            const double ea = edge(b.p, c.p, p), eb = edge(c.p, a.p, p), ec = edge(a.p, b.p, p);
            if (!inside(ea, b.p, c.p) || !inside(eb, c.p, a.p) || !inside(ec, a.p, b.p)) continue;
            const double depth = (ea * a.depth + eb * b.depth + ec * c.depth) / area;  // barycentric
            float& texel = map.depth[static_cast<std::size_t>(y) * map.resolution + x];
            texel = std::min(texel, static_cast<float>(std::max(0.0, depth)));
        }
}

// The texel containing t in [0, 1] along one axis (t = 1 belongs to the last texel).
int texel_of(double t, int resolution) { return std::min(static_cast<int>(t * resolution), resolution - 1); }

bool in_unit_range(double t) { return t >= 0.0 && t <= 1.0; }  // false for NaN

}  // namespace

DepthMap rasterize_depth(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object,
                         const ShadowMap& map, int resolution) {
    DepthMap out{resolution, std::vector<float>(static_cast<std::size_t>(resolution) * resolution, 1.0f)};
    for (std::size_t i = 0; i < triangles.triangles.size(); ++i) {
        if (!casts_per_object.at(triangles.object[i])) continue;
        std::array<glm::dvec4, 3> homogeneous;
        for (int k = 0; k < 3; ++k)
            homogeneous[k] = map.world_to_uvz * glm::dvec4(triangles.vertices[triangles.triangles[i][k]], 1.0);
        const Polygon polygon = clip_to_map(homogeneous);
        std::vector<ScreenVertex> screen;
        for (const glm::dvec4& h : polygon) screen.push_back(to_screen(h, resolution));
        for (std::size_t k = 1; k + 1 < screen.size(); ++k) draw_triangle(screen[0], screen[k], screen[k + 1], out);
    }
    return out;
}

bool in_shadow(const DepthMap& depth, const ShadowMap& map, const glm::dvec3& world_point, double bias) {
    const glm::dvec4 h = map.world_to_uvz * glm::dvec4(world_point, 1.0);
    if (!(h.w > 0.0)) return false;
    const double u = h.x / h.w, v = h.y / h.w;
    if (!in_unit_range(u) || !in_unit_range(v)) return false;
    const double d = (h.z - map.z_bias_scale * bias) / h.w;
    return d > depth.at(texel_of(u, depth.resolution), texel_of(v, depth.resolution));
}

}  // namespace shadowlab
