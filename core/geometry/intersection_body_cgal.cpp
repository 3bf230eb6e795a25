// The CGAL paths of the intersection body. V = frustum ∩ S and B = hull(V ∪ light) ∩ S are built
// on closed triangulated surface meshes: convex_hull_3 makes the hulls (the frustum's from its 8
// corners) and Polygon_mesh_processing::clip cuts each hull to S in one corefinement with the exact
// box mesh. One template serves both kernels; with epeck nothing is rounded before the final
// conversion. Avoided on purpose: halfspace_intersection_3 (reported to return wrong geometry on
// duplicate planes) and PMP::clip by a plane, which cuts with a polygon whose corners epick rounds
// off the plane (x = 2 cut at 1.9999999999999996), so cascaded cuts leave slivers and
// self-intersections on which the next corefinement hangs or crashes.
#include "geometry/intersection_body.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/clip.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

namespace shadowlab {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;

template <class K>
using Mesh = CGAL::Surface_mesh<typename K::Point_3>;

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// True when the points span a 3D volume (exact predicates: a flat set is caught).
template <class Point>
bool has_volume(const std::vector<Point>& p) {
    std::size_t i = 1, j;
    while (i < p.size() && p[i] == p[0]) ++i;  // a second point
    for (j = i + 1; j < p.size() && CGAL::collinear(p[0], p[i], p[j]); ++j) {
    }                                               // a third, off their line
    for (std::size_t k = j + 1; k < p.size(); ++k)  // a fourth, off their plane
        if (!CGAL::coplanar(p[0], p[i], p[j], p[k])) return true;
    return false;
}

template <class K>
std::vector<typename K::Point_3> points_of(const Mesh<K>& mesh) {
    std::vector<typename K::Point_3> points;
    for (auto v : mesh.vertices()) points.push_back(mesh.point(v));
    return points;
}

// Clips a closed convex mesh to the box, in one corefinement with the exact box mesh (skipped when
// the mesh is inside already).
template <class K>
void clip_to_box(Mesh<K>& mesh, const Aabb& box) {
    const typename K::Iso_cuboid_3 cuboid(box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z);
    const auto points = points_of<K>(mesh);
    if (std::any_of(points.begin(), points.end(), [&](const auto& p) { return cuboid.has_on_unbounded_side(p); }))
        PMP::clip(mesh, cuboid, CGAL::parameters::clip_volume(true));
}

// Converts a closed convex mesh to a ConvexPolyhedron, rounding the points to double only here.
// A face is a region of edge-connected triangles whose vertices lie within a tolerance (1e-13 of
// the coordinates' size) of the plane of its largest triangle: slivers and degenerate triangles, which
// exact cuts and epick's rounded ones leave and whose own planes are meaningless, join a neighbour.
// A region whose boundary is not one loop stays as triangles; vertices inside an edge are dropped.
template <class K>
ConvexPolyhedron to_polyhedron(Mesh<K>& mesh) {
    using Face = typename Mesh<K>::Face_index;
    using Halfedge = typename Mesh<K>::Halfedge_index;
    mesh.collect_garbage();  // dense indices
    std::vector<glm::dvec3> point;
    double size = 0.0;
    for (auto v : mesh.vertices()) {
        const auto& p = mesh.point(v);
        // exact() first: Lazy_exact_nt's to_double only promises a relative precision of 1e-5.
        auto to_double = [](const auto& x) { return CGAL::to_double(CGAL::exact(x)); };
        point.emplace_back(to_double(p.x()), to_double(p.y()), to_double(p.z()));
        size = std::max({size, std::abs(point.back().x), std::abs(point.back().y), std::abs(point.back().z)});
    }
    const double tolerance = 1e-13 * size;
    // A mesh thinner than the tolerance (volume <= tolerance * area: empty, flat, or a sliver left
    // by a grazing cut) has faces that double precision cannot orient: it converts to empty.
    double volume = 0.0, area_sum = 0.0;
    for (Face f : mesh.faces()) {
        const Halfedge h = mesh.halfedge(f);
        const glm::dvec3 o = point[0], a = point[mesh.source(h)] - o, b = point[mesh.target(h)] - o,
                         c = point[mesh.target(mesh.next(h))] - o;
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
        area_sum += glm::length(glm::cross(b - a, c - a)) / 2.0;
    }
    if (!(volume > tolerance * area_sum)) return {};
    auto source = [&](Halfedge h) { return int(mesh.source(h)); };
    auto area = [&](Face f) {  // twice the area vector
        const Halfedge h = mesh.halfedge(f);
        const glm::dvec3 a = point[mesh.source(h)];
        return glm::cross(point[mesh.target(h)] - a, point[mesh.target(mesh.next(h))] - a);
    };
    std::vector<Face> by_area(mesh.faces().begin(), mesh.faces().end());
    std::sort(by_area.begin(), by_area.end(),
              [&](Face f, Face g) { return glm::length(area(f)) > glm::length(area(g)); });
    ConvexPolyhedron out;  // first with mesh vertex indices
    std::vector<int> region(mesh.number_of_faces(), -1);
    std::vector<bool> walked(mesh.number_of_halfedges(), false);
    for (Face seed : by_area) {
        if (region[seed] >= 0 || glm::length(area(seed)) == 0.0) continue;
        // Grow the region from the seed; sum the area vectors for the normal.
        const Plane seed_plane = Plane::through(point[source(mesh.halfedge(seed))], area(seed));
        const int id = int(seed);
        std::vector<Face> faces{seed};
        region[seed] = id;
        glm::dvec3 normal(0.0);
        for (std::size_t i = 0; i < faces.size(); ++i) {
            normal += area(faces[i]);
            for (Halfedge e : CGAL::halfedges_around_face(mesh.halfedge(faces[i]), mesh)) {
                const Halfedge o = mesh.opposite(e);
                const Face n = mesh.face(o);
                if (region[n] < 0 &&
                    std::abs(seed_plane.signed_distance(point[mesh.target(mesh.next(o))])) <= tolerance) {
                    region[n] = id;
                    faces.push_back(n);
                }
            }
        }
        const Plane plane = Plane::through(point[source(mesh.halfedge(seed))], normal);
        // Walk the region's boundary loops (counter-clockwise, as the triangles are).
        std::vector<std::vector<int>> loops;
        for (Face f : faces)
            for (Halfedge e : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
                if (walked[e] || region[mesh.face(mesh.opposite(e))] == id) continue;
                loops.emplace_back();
                for (Halfedge b = e; !walked[b];) {
                    walked[b] = true;
                    loops.back().push_back(source(b));
                    b = mesh.next(b);  // turn around b's target to the next boundary halfedge
                    while (region[mesh.face(mesh.opposite(b))] == id) b = mesh.next(mesh.opposite(b));
                }
            }
        // Emit one polygon, or the region's triangles, all on the region's plane.
        if (loops.size() == 1) {
            out.faces.push_back({std::move(loops[0]), plane});
        } else {
            for (Face f : faces) {
                std::vector<int> loop;
                for (Halfedge b : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) loop.push_back(source(b));
                out.faces.push_back({std::move(loop), plane});
            }
        }
    }
    // Drop the vertices on just two faces and within the tolerance of the line of their loop
    // neighbours, unless a face would keep fewer than 3; number the rest densely.
    std::vector<int> faces_at(point.size(), 0), index(point.size(), -1);
    for (const PolyFace& f : out.faces)
        for (int i : f.loop) ++faces_at[i];
    for (const PolyFace& f : out.faces)
        for (std::size_t j = 0, n = f.loop.size(); j < n; ++j) {
            const glm::dvec3 u = point[f.loop[(j + n - 1) % n]], v = point[f.loop[j]], w = point[f.loop[(j + 1) % n]];
            if (!(glm::length(glm::cross(w - u, v - u)) <= tolerance * glm::length(w - u)) || u == w)
                faces_at[f.loop[j]] = 0;
        }
    for (const PolyFace& f : out.faces)
        if (f.loop.size() - std::count_if(f.loop.begin(), f.loop.end(), [&](int i) { return faces_at[i] == 2; }) < 3)
            for (int i : f.loop) faces_at[i] = 0;
    for (PolyFace& f : out.faces) {
        std::erase_if(f.loop, [&](int i) { return faces_at[i] == 2; });
        for (int& i : f.loop) {
            if (index[i] < 0) {
                index[i] = int(out.vertices.size());
                out.vertices.push_back(point[i]);
            }
            i = index[i];
        }
    }
    return out;
}

// The algorithm, for one kernel.
template <class K>
IntersectionBody body_with_kernel(const BodyInput& input) {
    using Point = typename K::Point_3;
    const Aabb& s = input.scene_bounds;
    const glm::dvec4& light = input.light;
    // Non-finite input, or a scene box without volume (empty or flat in an axis), gives an empty body.
    if (s.empty() || !finite(s.min) || !finite(s.max) || glm::any(glm::lessThanEqual(s.extent(), glm::dvec3(0.0))))
        return {};
    for (const glm::dvec3& corner : input.frustum.corners)
        if (!finite(corner)) return {};
    if (!finite(glm::dvec3(light)) || !std::isfinite(light.w) ||
        (light.w != 0.0 && !finite(glm::dvec3(light) / light.w)))
        return {};
    // The frustum as a closed triangulated mesh: the hull of its corners (a flat one sees nothing).
    std::vector<Point> points;
    for (const glm::dvec3& c : input.frustum.corners) points.emplace_back(c.x, c.y, c.z);
    if (!has_volume(points)) return {};
    Mesh<K> visible;
    CGAL::convex_hull_3(points.begin(), points.end(), visible);
    // V = frustum ∩ S; nothing visible, or a contact or sliver without volume, gives an empty body.
    clip_to_box<K>(visible, s);
    ConvexPolyhedron visible_poly = to_polyhedron<K>(visible);
    if (visible_poly.empty()) return {};
    // The points to hull: V's vertices and the point light, or V's vertices pushed beyond S toward the light.
    points = points_of<K>(visible);
    const glm::dvec3 toward(light);
    if (light.w != 0.0) {
        const glm::dvec3 l = toward / light.w;
        points.emplace_back(l.x, l.y, l.z);
    } else if (glm::dot(toward, toward) > 0.0) {  // a zero direction leaves B = V
        const glm::dvec3 push = 2.0 * s.diagonal() * glm::normalize(toward);
        const typename K::Vector_3 shift(push.x, push.y, push.z);
        for (std::size_t i = 0, n = points.size(); i < n; ++i) points.push_back(points[i] + shift);
    }
    // B = hull of those points clipped to S (it contains V).
    Mesh<K> body;
    CGAL::convex_hull_3(points.begin(), points.end(), body);
    clip_to_box<K>(body, s);
    return {std::move(visible_poly), to_polyhedron<K>(body)};
}

}  // namespace

IntersectionBody intersection_body_cgal(const BodyInput& input, bool exact) {
    return exact ? body_with_kernel<CGAL::Epeck>(input) : body_with_kernel<CGAL::Epick>(input);
}

}  // namespace shadowlab
