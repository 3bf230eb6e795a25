#include "methods/map_coverage.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>

#include "geometry/convex_polyhedron.hpp"
#include "maps/map_lookup.hpp"
#include "math/matrix.hpp"

namespace shadowlab {
namespace {

// (u, v, d) counts as within [0, 1] up to this: a map fitted to a point holds it up to rounding.
constexpr double kUnitTolerance = 1e-7;
// Receiver boxes named in a note, the rest counted.
constexpr size_t kNamedReceivers = 3;

// The world half-space c . (p, 1) <= 0 as a plane; nullopt when c does not depend on p (an
// orthographic map's constant w), which keeps everything or nothing.
std::optional<Plane> half_space(const glm::dvec4& c) {
    const double length = glm::length(glm::dvec3(c));
    if (!(length > 0.0)) return std::nullopt;
    return Plane{glm::dvec3(c) / length, c.w / length};
}

// Where a linear map puts (u, v) in [0, 1]^2 in front of its centre: u w >= 0, u w <= w, likewise
// v, and w >= 0, each linear in the world point (p, 1).
std::vector<Plane> uv_square(const ShadowMap& map) {
    const glm::dvec4 u = row(map.world_to_uvz, 0), v = row(map.world_to_uvz, 1), w = row(map.world_to_uvz, 3);
    std::vector<Plane> planes;
    for (const glm::dvec4& c : {-u, u - w, -v, v - w, -w})
        if (const std::optional<Plane> plane = half_space(c)) planes.push_back(*plane);
    return planes;
}

// The vertices of the box cut to the planes' kept sides (none when they miss it).
std::vector<glm::dvec3> vertices_within(const Aabb& box, const std::vector<Plane>& planes, double tolerance) {
    ConvexPolyhedron part = ConvexPolyhedron::box(box);
    for (const Plane& plane : planes) part = clip(part, plane, tolerance);
    return part.vertices;
}

bool in_unit_cube(const glm::dvec4& h) {
    const glm::dvec3 uvz = glm::dvec3(h) / h.w;
    return h.w > 0.0 && glm::all(glm::greaterThanEqual(uvz, glm::dvec3(-kUnitTolerance))) &&
           glm::all(glm::lessThanEqual(uvz, glm::dvec3(1.0 + kUnitTolerance)));
}

bool held_by_a_map(const ShadowSetup& setup, const glm::dvec3& p) {
    return std::any_of(setup.maps.begin(), setup.maps.end(),
                       [&](const ShadowMap& map) { return in_unit_cube(map_homogeneous(map, p)); });
}

// The area of the convex hull of points in the plane: Andrew's monotone chain, counter-clockwise
// and closed (its last point is its first), then the shoelace formula.
double hull_area(std::vector<glm::dvec2> points) {
    if (points.size() < 3) return 0.0;
    std::sort(points.begin(), points.end(),
              [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    const auto turn = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    std::vector<glm::dvec2> hull(2 * points.size());
    size_t k = 0;
    for (size_t i = 0; i < points.size(); ++i) {  // lower chain
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
        hull[k++] = points[i];
    }
    for (size_t i = points.size() - 1, lower = k + 1; i > 0; --i) {  // upper chain
        while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i - 1]) <= 0.0) --k;
        hull[k++] = points[i - 1];
    }
    double twice_area = 0.0;
    for (size_t i = 0; i + 1 < k; ++i) twice_area += hull[i].x * hull[i + 1].y - hull[i + 1].x * hull[i].y;
    return 0.5 * twice_area;
}

// The share of the map's [0,1]^2 that the view region's points project onto.
double view_share(const ShadowMap& map, const ConvexPolyhedron& view, double tolerance) {
    ConvexPolyhedron seen = view;
    for (const Plane& plane : uv_square(map)) seen = clip(seen, plane, tolerance);
    std::vector<glm::dvec2> uv;
    for (const glm::dvec3& p : seen.vertices)
        if (const glm::dvec4 h = map_homogeneous(map, p); h.w > 0.0) uv.push_back(glm::dvec2(h) / h.w);
    return std::clamp(hull_area(uv), 0.0, 1.0);
}

double tile_area(const ShadowMap& map) { return (map.viewport.z - map.viewport.x) * (map.viewport.w - map.viewport.y); }

std::string text(const glm::dvec3& p) {
    char buffer[96];
    const glm::dvec3 q = p + 0.0;  // -0 (a flat box's side) printed as 0
    std::snprintf(buffer, sizeof buffer, "(%.3g, %.3g, %.3g)", q.x, q.y, q.z);
    return buffer;
}

std::string percent(double share) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1f%%", 100.0 * share);
    return buffer;
}

}  // namespace

MapCoverage map_coverage(const ShadowInputs& in, const ShadowSetup& setup) {
    MapCoverage coverage;
    const double tolerance = 1e-9 * in.scene_bounds.diagonal();
    const std::vector<Plane> frustum(in.frustum.planes.begin(), in.frustum.planes.end());
    for (const Aabb& receiver : in.receivers) {
        bool missed = false;
        for (const glm::dvec3& p : vertices_within(receiver, frustum, tolerance)) {
            coverage.receiver_points.push_back(p);
            if (held_by_a_map(setup, p)) continue;
            coverage.missed_points.push_back(p);
            missed = true;
        }
        if (missed) coverage.missed_receivers.push_back(receiver);
    }
    // A caster's part under a map's (u, v) square, before its near plane: what depth clipping cuts.
    for (const Aabb& caster : in.casters) {
        const size_t before = coverage.clipped_points.size();
        for (const ShadowMap& map : setup.maps)
            for (const glm::dvec3& p : vertices_within(caster, uv_square(map), tolerance))
                if (const glm::dvec4 h = map_homogeneous(map, p); h.w > 0.0 && h.z / h.w < -kUnitTolerance)
                    coverage.clipped_points.push_back(p);
        coverage.clipped_casters += coverage.clipped_points.size() > before;
    }
    ConvexPolyhedron view = ConvexPolyhedron::box(in.scene_bounds);
    for (const Plane& plane : frustum) view = clip(view, plane, tolerance);
    double area = 0.0, outside = 0.0;
    for (const ShadowMap& map : setup.maps) {
        area += tile_area(map);
        outside += tile_area(map) * (1.0 - view_share(map, view, tolerance));
    }
    coverage.texels_outside_view = area > 0.0 ? outside / area : 0.0;
    return coverage;
}

std::vector<Note> coverage_notes(const MapCoverage& c) {
    std::vector<Note> notes;
    if (!c.missed_points.empty()) {
        std::string boxes;
        for (size_t i = 0; i < std::min(c.missed_receivers.size(), kNamedReceivers); ++i)
            boxes += (i ? "; " : "") + text(c.missed_receivers[i].min) + ".." + text(c.missed_receivers[i].max);
        if (c.missed_receivers.size() > kNamedReceivers)
            boxes += "; and " + std::to_string(c.missed_receivers.size() - kNamedReceivers) + " more";
        notes.push_back({NoteKind::missed_receivers,
                         std::to_string(c.missed_points.size()) + " of " + std::to_string(c.receiver_points.size()) +
                             " visible receiver points, on " + std::to_string(c.missed_receivers.size()) +
                             " receiver box(es) " + boxes});
    }
    if (c.clipped_casters > 0)
        notes.push_back({NoteKind::casters_before_near_plane, std::to_string(c.clipped_casters) + " caster box(es), " +
                                                                  std::to_string(c.clipped_points.size()) +
                                                                  " points at d < 0"});
    if (c.texels_outside_view > kWastedShareNoted)
        notes.push_back({NoteKind::texels_outside_view, percent(c.texels_outside_view) + " of the maps' texels"});
    return notes;
}

}  // namespace shadowlab
