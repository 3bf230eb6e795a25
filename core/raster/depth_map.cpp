// Triangles are clipped in homogeneous space, divided by w, and sampled at texel centres with edge
// functions; d / w is affine in (u / w, v / w), so screen-space interpolation of it is exact.
#include "raster/depth_map.hpp"

#include "geometry/homogeneous_clip.hpp"
#include "math/parallel_rows.hpp"
#include "maps/map_lookup.hpp"
#include "raster/paraboloid_edges.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <thread>
#include <utility>
#include <vector>

namespace shadowlab {
namespace {

constexpr double kMinRelativeW = 1e-9;  // clipped w stays above this fraction of the triangle's largest |w|

using Polygon = HomogeneousPolygon;  // (u, v, d_pre, w)

// The part of a polygon with w > 0 and 0 <= u, v <= w: in front of the map's centre and on it.
// The w plane sits a hair above 0, relative to the triangle's scale, so the division stays finite.
Polygon clip_to_map(Polygon polygon) {
    double largest_w = 0.0;
    for (const glm::dvec4& h : polygon) largest_w = std::max(largest_w, std::abs(h.w));
    const double min_w = kMinRelativeW * largest_w;
    if (!(min_w > 0.0)) return {};
    const ClipPlane planes[] = {{{0, 0, 0, 1}, min_w}, {{1, 0, 0, 0}, 0.0}, {{-1, 0, 0, 1}, 0.0},
                                {{0, 1, 0, 0}, 0.0},   {{0, -1, 0, 1}, 0.0}};
    for (const ClipPlane& plane : planes) polygon = clip(polygon, plane);
    return polygon;
}

// A vertex after division: position in texels of the texture, depth in map units.
struct ScreenVertex {
    glm::dvec2 p;
    double depth;
};

ScreenVertex to_screen(const glm::dvec4& h, const ShadowMap& map, int resolution) {
    return {texture_uv(map, glm::dvec2(h.x, h.y) / h.w) * static_cast<double>(resolution), h.z / h.w};
}

// The texels of one map's tile: first and last column and row.
struct TexelRange {
    glm::ivec2 first, last;
};

TexelRange tile_texels(const ShadowMap& map, int resolution) {
    return {texel_of(map, glm::dvec2(0.0), resolution), texel_of(map, glm::dvec2(1.0), resolution)};
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

// First and last texel whose centre (i + 0.5) lies in [lo, hi], within [first, last].
std::pair<int, int> texel_span(double lo, double hi, int first, int last) {
    return {std::max(first, static_cast<int>(std::ceil(lo - 0.5))), std::min(last, static_cast<int>(std::floor(hi - 0.5)))};
}

void draw_triangle(ScreenVertex a, ScreenVertex b, ScreenVertex c, const TexelRange& tile, DepthMap& map) {
    double area = edge(a.p, b.p, c.p);
    if (area == 0.0) return;
    if (area < 0.0) {  // both windings are drawn: make it counter-clockwise
        std::swap(b, c);
        area = -area;
    }
    const glm::dvec2 lo = glm::min(a.p, glm::min(b.p, c.p)), hi = glm::max(a.p, glm::max(b.p, c.p));
    const auto [x0, x1] = texel_span(lo.x, hi.x, tile.first.x, tile.last.x);
    const auto [y0, y1] = texel_span(lo.y, hi.y, tile.first.y, tile.last.y);
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

// A paraboloid map's projected triangle: the part on its hemisphere's side, cut where the plane
// distance, interpolated along the projected edges, crosses 0 (as gl_ClipDistance does).
Polygon on_hemisphere(const ShadowMap& map, const std::array<glm::dvec3, 3>& world, const Polygon& projected) {
    const std::array<double, 3> side{hemisphere_side(map, world[0]), hemisphere_side(map, world[1]),
                                     hemisphere_side(map, world[2])};
    return clip_where(projected, [&](std::size_t i) { return side[i]; });
}

// The map's caster triangles after clipping and division, as fans of screen vertices.
std::vector<std::array<ScreenVertex, 3>> screen_triangles(const WorldTriangles& triangles,
                                                          const std::vector<bool>& casts_per_object,
                                                          const ShadowMap& map, int resolution) {
    std::vector<std::array<ScreenVertex, 3>> out;
    for (std::size_t i = 0; i < triangles.triangles.size(); ++i) {
        if (!casts_per_object.at(triangles.object[i])) continue;
        std::array<glm::dvec3, 3> world;
        std::array<glm::dvec4, 3> homogeneous;
        for (int k = 0; k < 3; ++k) {
            world[k] = triangles.vertices[triangles.triangles[i][k]];
            homogeneous[k] = map_homogeneous(map, world[k]);
        }
        Polygon polygon(homogeneous.begin(), homogeneous.end());
        if (map.projection == Projection::paraboloid) polygon = on_hemisphere(map, world, polygon);
        polygon = clip_to_map(std::move(polygon));
        std::vector<ScreenVertex> screen;
        for (const glm::dvec4& h : polygon) screen.push_back(to_screen(h, map, resolution));
        for (std::size_t k = 1; k + 1 < screen.size(); ++k) out.push_back({screen[0], screen[k], screen[k + 1]});
    }
    return out;
}

// The triangles filled on every core, each thread a band of the tile's rows: every texel is written
// by one thread, and its least depth does not depend on the order, so the result is the same.
void draw_map(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object, const ShadowMap& map,
              DepthMap& out) {
    const TexelRange tile = tile_texels(map, out.resolution);
    const std::vector<std::array<ScreenVertex, 3>> screen =
        screen_triangles(triangles, casts_per_object, map, out.resolution);
    const int rows = tile.last.y - tile.first.y + 1, bands = std::max(1, std::min(row_threads(), rows));
    std::vector<std::thread> workers;
    for (int b = 0; b < bands; ++b)
        workers.emplace_back([&, b] {
            TexelRange band = tile;
            band.first.y = tile.first.y + rows * b / bands;
            band.last.y = tile.first.y + rows * (b + 1) / bands - 1;
            for (const std::array<ScreenVertex, 3>& t : screen) draw_triangle(t[0], t[1], t[2], band, out);
        });
    for (std::thread& w : workers) w.join();
}

}  // namespace

DepthMap rasterize_depth(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object,
                         const ShadowSetup& setup, int resolution) {
    DepthMap out{resolution, std::vector<float>(static_cast<std::size_t>(resolution) * resolution, 1.0f)};
    for (const ShadowMap& map : setup.maps) {
        if (splits_casters(map))  // split for this map's curvature and tile: the edges a GPU draws straight
            draw_map(split_casters(triangles, casts_per_object, map, resolution), casts_per_object, map, out);
        else
            draw_map(triangles, casts_per_object, map, out);
    }
    return out;
}

}  // namespace shadowlab
