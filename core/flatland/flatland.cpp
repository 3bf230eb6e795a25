#include "flatland/flatland.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "geometry/intersection_body.hpp"
#include "geometry/plane_section.hpp"
#include "maps/map_lookup.hpp"
#include "maps/projection_kind.hpp"
#include "math/invariant.hpp"

namespace shadowlab {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kCellsAlongLongerSide = 480;
constexpr double kFrameMargin = 0.06;  // of the frame's longer side, on every side
constexpr double kUnitCubeSlack = 1e-9;
constexpr double kDensePercentile = 0.9;

// (u, v, d) of p under map `m` where the setup's selection gives p that map and p lies in its unit
// cube; NaN elsewhere.
glm::dvec3 served_uvz(const ShadowSetup& setup, int m, const glm::dvec3& p) {
    if (select_map(setup, p) != m) return glm::dvec3(kNaN);
    const glm::dvec4 h = map_homogeneous(setup.maps[m], p);
    if (!(h.w > 0.0)) return glm::dvec3(kNaN);
    const glm::dvec3 uvz = glm::dvec3(h) / h.w;
    const bool inside = glm::all(glm::greaterThanEqual(uvz, glm::dvec3(-kUnitCubeSlack))) &&
                        glm::all(glm::lessThanEqual(uvz, glm::dvec3(1.0 + kUnitCubeSlack)));
    return inside ? uvz : glm::dvec3(kNaN);
}

// The (s, t) rectangle shown: B's section (the scene's, when the plane misses B) and the eye.
void frame_around(Flatland& f, const std::vector<glm::dvec3>& shown) {
    glm::dvec2 lo(0.0), hi(0.0);  // the eye, at the origin
    for (const glm::dvec3& p : shown) {
        lo = glm::min(lo, f.plane.coordinates(p));
        hi = glm::max(hi, f.plane.coordinates(p));
    }
    const double margin = kFrameMargin * std::max(hi.x - lo.x, hi.y - lo.y);
    f.frame_min = lo - margin;
    f.frame_max = hi + margin;
}

PlaneGrid grid_over_frame(const Flatland& f) {
    const glm::dvec2 size = f.frame_max - f.frame_min;
    const double cell = std::max(size.x, size.y) / kCellsAlongLongerSide;
    return {.origin = f.plane.eye,
            .along = f.plane.along,
            .across = f.plane.across,
            .min = f.frame_min,
            .max = f.frame_max,
            .cells = glm::max(glm::ivec2(glm::ceil(size / cell)), glm::ivec2(1))};
}

// One family of texel boundaries: map m's u (axis 0) or v (axis 1) in texels, sampled on the grid.
struct TexelFamily {
    int map = 0, axis = 0, texels = 0;
    GridSamples samples;
    double least = INFINITY, most = -INFINITY;  // the field's range over the samples
    double dense = 0.0;  // boundaries per world unit between neighbouring samples, at kDensePercentile of them

    double field(const ShadowSetup& setup, const glm::dvec3& p) const {
        return served_uvz(setup, map, p)[axis] * texels;
    }
};

TexelFamily texel_family(const PlaneGrid& g, const std::vector<glm::dvec3>& uvz, int map, int axis, int texels) {
    TexelFamily family{map, axis, texels, {g, {}}, INFINITY, -INFINITY, 0.0};
    for (const glm::dvec3& sample : uvz) {
        family.samples.values.push_back(sample[axis] * texels);
        if (std::isnan(sample[axis])) continue;
        family.least = std::min(family.least, family.samples.values.back());
        family.most = std::max(family.most, family.samples.values.back());
    }
    const glm::dvec2 cell = g.cell_size();
    std::vector<double> densities;
    for (int j = 0; j < g.cells.y; ++j)
        for (int i = 0; i < g.cells.x; ++i) {
            const double value = family.samples.at(i, j);
            const double across_s = std::abs(family.samples.at(i + 1, j) - value) / cell.x,
                         across_t = std::abs(family.samples.at(i, j + 1) - value) / cell.y;
            if (!std::isnan(across_s + across_t)) densities.push_back(std::hypot(across_s, across_t));
        }
    if (!densities.empty()) {
        const auto at = densities.begin() + static_cast<std::ptrdiff_t>(kDensePercentile * (densities.size() - 1));
        std::nth_element(densities.begin(), at, densities.end());
        family.dense = *at;
    }
    return family;
}

// The least power of two k at which the densest map shows at most kMostLinesAcross boundaries of
// its u and v together across the frame's longer side, each family at its kDensePercentile density:
// the few most crowded places (a warp's near face) may run together, the rest stays apart.
int readable_stride(const std::vector<TexelFamily>& families, const Flatland& f) {
    const glm::dvec2 size = f.frame_max - f.frame_min;
    std::vector<double> per_map;
    for (const TexelFamily& family : families) {
        if (family.map >= static_cast<int>(per_map.size())) per_map.resize(family.map + 1, 0.0);
        per_map[family.map] += family.dense;
    }
    const double densest = per_map.empty() ? 0.0 : *std::max_element(per_map.begin(), per_map.end());
    int stride = 1;
    while (densest * std::max(size.x, size.y) / stride > kMostLinesAcross) stride *= 2;
    return stride;
}

// Every k-th boundary of a family across the plane: none when the family's boundaries run along the
// plane (its field spans less than one texel over the frame: the plane lies inside one texel's slab).
void trace_family(Flatland& f, const ShadowSetup& setup, const TexelFamily& family) {
    if (!(family.most - family.least >= 1.0)) return;
    const ScalarField field = [&](const glm::dvec3& p) { return family.field(setup, p); };
    const int first = static_cast<int>(std::ceil(std::max(0.0, family.least) / f.stride)) * f.stride;
    const int last = static_cast<int>(std::floor(std::min<double>(family.texels, family.most)));
    std::vector<double> levels;
    for (int index = first; index <= last; index += f.stride) levels.push_back(index);
    std::vector<std::vector<Polyline>> curves = level_curves(family.samples, field, levels);
    for (size_t k = 0; k < levels.size(); ++k)
        for (Polyline& line : curves[k])
            f.texel_lines.push_back({family.map, family.axis, static_cast<int>(levels[k]), std::move(line)});
}

// A map's volume cut by the plane: its frustum's section for a projective kind, else the level
// curve where the least of u, 1 − u, v, 1 − v, d, 1 − d crosses 0.
MapSection map_section(const Flatland& f, const ShadowMap& map, int index, const PlaneGrid& grid) {
    if (projection_kind(map).projective())
        return {index, 0, {closed_outline(plane_section(edges_of(map_volume(map)), f.plane.plane()))}};
    const ScalarField inside = [&](const glm::dvec3& p) {
        const glm::dvec4 h = map_homogeneous(map, p);
        if (!(h.w > 0.0)) return kNaN;
        const glm::dvec3 uvz = glm::dvec3(h) / h.w;
        const glm::dvec3 low = glm::min(uvz, 1.0 - uvz);
        return std::min({low.x, low.y, low.z});
    };
    return {index, 0, level_curves(sample_field(grid, inside), inside, 0.0)};
}

}  // namespace

Flatland flatland(const ShadowInputs& in, const ShadowSetup& setup, int texture_resolution) {
    Flatland f;
    FlatlandChoice choice = flatland_plane(in.camera, in.light);
    f.plane = choice.plane;
    if (choice.fallback) f.fallbacks.push_back(*choice.fallback);
    const Plane plane = f.plane.plane();
    f.frustum = plane_section(edges_of(in.frustum), plane);
    const IntersectionBody body = intersection_body_float({in.frustum, in.scene_bounds, in.light.homogeneous()});
    if (!body.body.empty()) f.body = plane_section(edges_of(body.body), plane);
    frame_around(f, f.body.empty() ? plane_section(edges_of(ConvexPolyhedron::box(in.scene_bounds)), plane) : f.body);
    const PlaneGrid grid = grid_over_frame(f);

    // Each grid point's map and (u, v, d) under it, once; then each map's two families.
    const GridSamples chosen = sample_field(grid, [&](const glm::dvec3& p) { return double(select_map(setup, p)); });
    std::vector<TexelFamily> families;
    for (int m = 0; m < static_cast<int>(setup.maps.size()); ++m) {
        std::vector<glm::dvec3> uvz(chosen.values.size(), glm::dvec3(kNaN));
        bool served = false;
        for (int j = 0; j <= grid.cells.y; ++j)
            for (int i = 0; i <= grid.cells.x; ++i)
                if (chosen.at(i, j) == m) {
                    uvz[static_cast<size_t>(j) * (grid.cells.x + 1) + i] = served_uvz(setup, m, grid.point(i, j));
                    served = true;
                }
        if (!served) continue;
        const int texels = static_cast<int>(std::lround(tile_resolution(setup.maps[m], texture_resolution)));
        f.texels = std::max(f.texels, texels);
        for (int axis : {0, 1}) families.push_back(texel_family(grid, uvz, m, axis, texels));
        f.map_volumes.push_back(map_section(f, setup.maps[m], m, grid));
        f.map_volumes.back().texels = texels;
    }
    f.stride = readable_stride(families, f);
    for (const TexelFamily& family : families) trace_family(f, setup, family);
    f.view_axis = view_axis_span(in);
    assert_invariant(f.stride >= 1);
    return f;
}

Polyline closed_outline(std::vector<glm::dvec3> polygon) {
    if (!polygon.empty()) polygon.push_back(polygon.front());
    return polygon;
}

int view_axis_crossings(const Flatland& f, double from, double to) {
    int count = 0;
    for (const TexelLine& line : f.texel_lines)
        for (size_t i = 0; i + 1 < line.points.size(); ++i) {
            const glm::dvec2 p = f.plane.coordinates(line.points[i]), q = f.plane.coordinates(line.points[i + 1]);
            if ((p.y < 0.0) == (q.y < 0.0)) continue;
            const double s = p.x + (q.x - p.x) * (p.y / (p.y - q.y));  // where the segment meets t = 0
            count += s >= from && s < to;
        }
    return count;
}

std::optional<AxisLineDensity> axis_line_density(const Flatland& f) {
    if (!f.view_axis) return std::nullopt;
    const double fifth = (f.view_axis->far - f.view_axis->near) / 5.0;
    AxisLineDensity d{.near = {f.view_axis->near, f.view_axis->near + fifth},
                      .far = {f.view_axis->far - fifth, f.view_axis->far}};
    d.near_lines = view_axis_crossings(f, d.near.near, d.near.far) / fifth;
    d.far_lines = view_axis_crossings(f, d.far.near, d.far.far) / fifth;
    return d;
}

std::vector<std::pair<glm::dvec3, glm::dvec3>> scene_section(const WorldTriangles& triangles,
                                                             const FlatlandPlane& flatland_plane) {
    const Plane plane = flatland_plane.plane();
    std::vector<std::pair<glm::dvec3, glm::dvec3>> segments;
    for (const std::array<int, 3>& t : triangles.triangles) {
        std::vector<glm::dvec3> crossings;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 &a = triangles.vertices[t[k]], &b = triangles.vertices[t[(k + 1) % 3]];
            const double da = plane.signed_distance(a), db = plane.signed_distance(b);
            if ((da < 0.0) != (db < 0.0)) crossings.push_back(a + (b - a) * (da / (da - db)));
        }
        if (crossings.size() == 2) segments.emplace_back(crossings[0], crossings[1]);
    }
    return segments;
}

}  // namespace shadowlab
