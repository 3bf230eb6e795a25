#include "views/polydata.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>

#include "geometry/homogeneous_clip.hpp"

namespace shadowlab {
namespace {

constexpr double kMinW = 1e-9;

// The half-spaces a placed primitive is cut to: w >= kMinW, the placement's own, and min <= x / w <= max
// on each axis of the clip box, written as linear forms in (x, y, z, w) so that they hold before the division.
std::vector<ClipPlane> clip_planes(const Placement& placement) {
    std::vector<ClipPlane> planes{{{0.0, 0.0, 0.0, 1.0}, kMinW}};
    planes.insert(planes.end(), placement.cut.begin(), placement.cut.end());
    if (!placement.clip) return planes;
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec4 above(0.0), below(0.0);
        above[axis] = 1.0, above.w = -placement.clip->min[axis];
        below[axis] = -1.0, below.w = placement.clip->max[axis];
        planes.push_back({above, 0.0});
        planes.push_back({below, 0.0});
    }
    return planes;
}

// Builds cells from homogeneous points of the space, each cut to the placement's half-spaces.
class CellBuilder {
public:
    explicit CellBuilder(const Placement& placement) : placement_(placement), planes_(clip_planes(placement)) {}

    glm::dvec4 in_space(const glm::dvec3& world) const { return placement_.to_space * glm::dvec4(world, 1.0); }

    void polygon(vtkCellArray* cells, HomogeneousPolygon polygon) {
        for (const ClipPlane& plane : planes_)
            if (polygon.size() >= 3) polygon = clip(polygon, plane);
        if (polygon.size() < 3) return void(++dropped_);
        insert(cells, polygon);
    }
    // The same for a triangle; one wholly inside (nearly every triangle of a scene) is inserted as it
    // is, without building a polygon to clip: the World view's town is 32,366 of them.
    void triangle(vtkCellArray* cells, const std::array<glm::dvec4, 3>& corners) {
        if (!std::all_of(corners.begin(), corners.end(), [this](const glm::dvec4& p) { return inside(p); }))
            return polygon(cells, {corners[0], corners[1], corners[2]});
        std::array<vtkIdType, 3> ids;
        for (int k = 0; k < 3; ++k) ids[k] = insert_point(corners[k]);
        cells->InsertNextCell(3, ids.data());
    }
    // The part of a -> b inside every half-space (Liang-Barsky on the linear forms); whether b itself is kept.
    bool segment(vtkCellArray* cells, const glm::dvec4& a, const glm::dvec4& b) {
        double t0 = 0.0, t1 = 1.0;
        for (const ClipPlane& plane : planes_) {
            const double da = glm::dot(plane.normal, a) - plane.offset, db = glm::dot(plane.normal, b) - plane.offset;
            if (da < 0.0 && db < 0.0) return ++dropped_, false;
            if (da < 0.0) t0 = std::max(t0, da / (da - db));
            if (db < 0.0) t1 = std::min(t1, da / (da - db));
        }
        if (t0 >= t1) return ++dropped_, false;
        insert(cells, {a + t0 * (b - a), a + t1 * (b - a)});
        return t1 == 1.0;
    }
    void vertex(vtkCellArray* cells, const glm::dvec4& p) {
        if (!inside(p)) return void(++dropped_);
        insert(cells, {p});
    }
    Placed finish(vtkCellArray* polys, vtkCellArray* lines, vtkCellArray* verts) {
        auto data = vtkSmartPointer<vtkPolyData>::New();
        data->SetPoints(points_);
        if (polys) data->SetPolys(polys);
        if (lines) data->SetLines(lines);
        if (verts) data->SetVerts(verts);
        return {data, dropped_};
    }

private:
    bool inside(const glm::dvec4& p) const {
        return std::all_of(planes_.begin(), planes_.end(),
                           [&](const ClipPlane& plane) { return glm::dot(plane.normal, p) >= plane.offset; });
    }
    vtkIdType insert_point(const glm::dvec4& h) {
        const glm::dvec3 p = glm::dvec3(h) / h.w;
        return points_->InsertNextPoint(p.x, p.y, p.z);
    }
    void insert(vtkCellArray* cells, const HomogeneousPolygon& vertices) {
        std::vector<vtkIdType> ids;
        for (const glm::dvec4& h : vertices) ids.push_back(insert_point(h));
        cells->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    }

    const Placement& placement_;
    std::vector<ClipPlane> planes_;
    vtkNew<vtkPoints> points_;
    size_t dropped_ = 0;
};

Placed edges(const Placement& placement, const std::vector<std::pair<glm::dvec3, glm::dvec3>>& segments) {
    CellBuilder b(placement);
    vtkNew<vtkCellArray> lines;
    for (const auto& [from, to] : segments) b.segment(lines, b.in_space(from), b.in_space(to));
    return b.finish(nullptr, lines, nullptr);
}

// A box's 12 edges: each corner joined to the corners one axis above it.
void add_box_edges(const Aabb& box, std::vector<std::pair<glm::dvec3, glm::dvec3>>& segments) {
    const auto corner = box.corners();
    for (int i = 0; i < 8; ++i)
        for (int bit : {1, 2, 4})
            if (!(i & bit)) segments.push_back({corner[i], corner[i | bit]});
}

Placed frustum_edges(const Frustum& f, const Placement& placement) {
    std::vector<std::pair<glm::dvec3, glm::dvec3>> segments;
    for (int i = 0; i < 4; ++i) {
        segments.push_back({f.corners[i], f.corners[(i + 1) % 4]});          // near rectangle
        segments.push_back({f.corners[4 + i], f.corners[4 + (i + 1) % 4]});  // far rectangle
        segments.push_back({f.corners[i], f.corners[4 + i]});                // sides
    }
    return edges(placement, segments);
}

// The faces' loops as world points: a polyhedron's faces; a polygon set's polygons, a vertex at
// infinity (w = 0) drawn `reach` away from its finite neighbour along its direction (a polygon with
// no finite vertex, a z-fail back cap, cannot be drawn and is left out).
std::vector<std::vector<glm::dvec3>> face_loops(const ConvexPolyhedron& poly, double) {
    std::vector<std::vector<glm::dvec3>> loops;
    for (const PolyFace& face : poly.faces) {
        std::vector<glm::dvec3>& loop = loops.emplace_back();
        for (int i : face.loop) loop.push_back(poly.vertices[i]);
    }
    return loops;
}

std::vector<std::vector<glm::dvec3>> face_loops(const PolygonSet& set, double reach) {
    std::vector<std::vector<glm::dvec3>> loops;
    for (const std::vector<int>& polygon : set.polygons) {
        const size_t n = polygon.size();
        std::vector<glm::dvec3> loop;
        for (size_t i = 0; i < n; ++i) {
            const glm::dvec4& v = set.vertices[polygon[i]];
            const glm::dvec4& before = set.vertices[polygon[(i + n - 1) % n]];
            const glm::dvec4& after = set.vertices[polygon[(i + 1) % n]];
            const glm::dvec4& anchor = v.w != 0.0 ? v : before.w != 0.0 ? before : after;
            if (anchor.w == 0.0) break;
            loop.push_back(glm::dvec3(anchor) / anchor.w +
                           (v.w != 0.0 ? glm::dvec3(0.0) : reach * glm::normalize(glm::dvec3(v))));
        }
        if (loop.size() == n) loops.push_back(loop);
    }
    return loops;
}

template <class Faces>
Placed faces(const Faces& shape, const Placement& placement) {
    CellBuilder b(placement);
    vtkNew<vtkCellArray> polys;
    for (const std::vector<glm::dvec3>& loop : face_loops(shape, placement.reach)) {
        HomogeneousPolygon polygon;
        for (const glm::dvec3& p : loop) polygon.push_back(b.in_space(p));
        b.polygon(polys, polygon);
    }
    return b.finish(polys, nullptr, nullptr);
}

template <class Faces>
Placed face_edges(const Faces& shape, const Placement& placement) {
    std::vector<std::pair<glm::dvec3, glm::dvec3>> segments;
    for (const std::vector<glm::dvec3>& loop : face_loops(shape, placement.reach))
        for (size_t i = 0; i < loop.size(); ++i) segments.push_back({loop[i], loop[(i + 1) % loop.size()]});
    return edges(placement, segments);
}

// The arc as 32 straight pieces, swept in the plane of its two directions.
Placed arc_polyline(const AngleArc& arc, const Placement& placement) {
    const glm::dvec3 a = glm::normalize(arc.from), b = glm::normalize(arc.to);
    const double angle = std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
    const glm::dvec3 across = b - glm::dot(a, b) * a;
    const glm::dvec3 side = glm::length(across) > 0.0 ? glm::normalize(across) : a;
    std::vector<std::pair<glm::dvec3, glm::dvec3>> pieces;
    auto at = [&](int i) {
        return arc.centre + arc.radius * (std::cos(angle * i / 32.0) * a + std::sin(angle * i / 32.0) * side);
    };
    for (int i = 0; i < 32; ++i) pieces.push_back({at(i), at(i + 1)});
    return edges(placement, pieces);
}

// A 12-sided cone with its apex at `tip`, pointing along `axis` (unit), in space coordinates: it
// reads as an arrow head from every side, unlike flat barbs.
void add_cone(CellBuilder& b, vtkCellArray* polys, const glm::dvec3& tip, const glm::dvec3& axis, double length) {
    const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(axis, helper)), v = glm::cross(axis, u);
    const glm::dvec3 base = tip - length * axis;
    const double radius = 0.35 * length;
    auto rim = [&](int i) {
        const double t = 2.0 * M_PI * i / 12.0;
        return glm::dvec4(base + radius * (std::cos(t) * u + std::sin(t) * v), 1.0);
    };
    HomogeneousPolygon bottom;
    for (int i = 0; i < 12; ++i) {
        b.polygon(polys, {glm::dvec4(tip, 1.0), rim(i), rim(i + 1)});
        bottom.push_back(rim(11 - i));
    }
    b.polygon(polys, bottom);
}

// The shaft cut like any segment; the head only where the tip itself is drawn, sized in the space
// (after the division by w), so a warp does not stretch it.
Placed arrow_shape(const Arrow& arrow, const Placement& placement) {
    CellBuilder b(placement);
    vtkNew<vtkCellArray> lines, polys;
    const glm::dvec4 from = b.in_space(arrow.from), to = b.in_space(arrow.to);
    if (b.segment(lines, from, to) && from.w > kMinW) {
        const glm::dvec3 tail = glm::dvec3(from) / from.w, tip = glm::dvec3(to) / to.w;
        const double length = glm::length(tip - tail);
        if (length > 0.0) {
            const double head = std::min(placement.head > 0.0 ? placement.head : 0.25 * length, 0.5 * length);
            add_cone(b, polys, tip, (tip - tail) / length, head);
        }
    }
    return b.finish(polys, lines, nullptr);
}

}  // namespace

std::optional<glm::dvec3> placed_point(const Placement& placement, const glm::dvec3& world) {
    const glm::dvec4 h = placement.to_space * glm::dvec4(world, 1.0);
    for (const ClipPlane& plane : clip_planes(placement))
        if (glm::dot(plane.normal, h) < plane.offset) return std::nullopt;
    return glm::dvec3(h) / h.w;
}

std::vector<glm::dvec3> object_colours(const Scene& scene) {
    static constexpr std::array<std::array<double, 3>, 6> palette{{{0.85, 0.62, 0.45},
                                                                   {0.62, 0.71, 0.84},
                                                                   {0.86, 0.80, 0.55},
                                                                   {0.70, 0.82, 0.66},
                                                                   {0.82, 0.66, 0.76},
                                                                   {0.75, 0.75, 0.78}}};
    std::vector<glm::dvec3> colours;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const auto& c = palette[i % palette.size()];
        colours.push_back(scene.objects[i].shape == Shape::plane ? glm::dvec3(0.80, 0.81, 0.76)
                                                                 : glm::dvec3(c[0], c[1], c[2]));
    }
    return colours;
}

Placed triangles_polydata(const WorldTriangles& triangles, const std::vector<bool>& keep,
                          const std::vector<glm::dvec3>& colours_per_object, const Placement& placement) {
    CellBuilder b(placement);
    std::vector<glm::dvec4> in_space;
    in_space.reserve(triangles.vertices.size());
    for (const glm::dvec3& v : triangles.vertices) in_space.push_back(b.in_space(v));
    vtkNew<vtkCellArray> polys;
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetName("colour");
    colours->SetNumberOfComponents(3);
    for (size_t t = 0; t < triangles.triangles.size(); ++t) {
        const int object = triangles.object[t];
        if (!keep[object]) continue;
        const auto& tri = triangles.triangles[t];
        const vtkIdType cells = polys->GetNumberOfCells();
        b.triangle(polys, {in_space[tri[0]], in_space[tri[1]], in_space[tri[2]]});
        if (polys->GetNumberOfCells() == cells) continue;
        const glm::dvec3 c = 255.0 * colours_per_object[object];
        colours->InsertNextTuple3(c.r, c.g, c.b);
    }
    Placed placed = b.finish(polys, nullptr, nullptr);
    placed.data->GetCellData()->SetScalars(colours);
    return placed;
}

Placed segments_polydata(const std::vector<std::pair<glm::dvec3, glm::dvec3>>& segments, const Placement& placement) {
    return edges(placement, segments);
}

Placed points_polydata(const std::vector<glm::dvec3>& points, const Placement& placement) {
    CellBuilder b(placement);
    vtkNew<vtkCellArray> verts;
    for (const glm::dvec3& p : points) b.vertex(verts, b.in_space(p));
    return b.finish(nullptr, nullptr, verts);
}

Placed boxes_polydata(const std::vector<Aabb>& boxes, const Placement& placement) {
    std::vector<std::pair<glm::dvec3, glm::dvec3>> segments;
    for (const Aabb& box : boxes) add_box_edges(box, segments);
    return edges(placement, segments);
}

Placed geometry_polydata(const TraceGeometry& geometry, const Placement& placement) {
    return std::visit(
        [&](const auto& g) -> Placed {
            using G = std::decay_t<decltype(g)>;
            if constexpr (std::is_same_v<G, PointSet>)
                return points_polydata(g.points, placement);
            else if constexpr (std::is_same_v<G, Aabb>)
                return boxes_polydata({g}, placement);
            else if constexpr (std::is_same_v<G, ConvexPolyhedron>)
                return faces(g, placement);
            else if constexpr (std::is_same_v<G, SegmentSet>)
                return edges(placement, g.segments);
            else if constexpr (std::is_same_v<G, PolygonSet>)
                return faces(g, placement);
            else if constexpr (std::is_same_v<G, Arrow>)
                return arrow_shape(g, placement);
            else if constexpr (std::is_same_v<G, AngleArc>)
                return arc_polyline(g, placement);
            else if constexpr (std::is_same_v<G, Label>)
                return points_polydata({g.at}, placement);
            else
                return frustum_edges(g, placement);
        },
        geometry);
}

std::optional<Placed> outline_polydata(const TraceGeometry& geometry, const Placement& placement) {
    if (const auto* poly = std::get_if<ConvexPolyhedron>(&geometry)) return face_edges(*poly, placement);
    if (const auto* set = std::get_if<PolygonSet>(&geometry)) return face_edges(*set, placement);
    return std::nullopt;
}

}  // namespace shadowlab
