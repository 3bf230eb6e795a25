#include "views/polydata.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>

namespace shadowlab {
namespace {

constexpr double kMinW = 1e-9;

std::optional<glm::dvec3> place(const glm::dmat4& to_space, const glm::dvec3& p) {
    const glm::dvec4 h = to_space * glm::dvec4(p, 1.0);
    if (!(h.w > kMinW)) return std::nullopt;
    return glm::dvec3(h) / h.w;
}

// Builds cells of `size` vertices from index lists, dropping those with a vertex behind w = 0.
class CellBuilder {
public:
    explicit CellBuilder(const glm::dmat4& to_space) : to_space_(to_space) {}

    vtkIdType point(const glm::dvec3& p) {
        const auto q = place(to_space_, p);
        if (!q) return -1;
        return points_->InsertNextPoint(q->x, q->y, q->z);
    }
    // A cell over already placed ids; false (and counted) when one of them was dropped.
    bool cell(vtkCellArray* cells, const std::vector<vtkIdType>& ids) {
        for (vtkIdType id : ids)
            if (id < 0) return ++dropped_, false;
        cells->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
        return true;
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
    glm::dmat4 to_space_;
    vtkNew<vtkPoints> points_;
    size_t dropped_ = 0;
};

Placed box_edges(const Aabb& box, const glm::dmat4& to_space) {
    CellBuilder b(to_space);
    std::array<vtkIdType, 8> id{};
    for (int i = 0; i < 8; ++i)
        id[i] = b.point({i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y, i & 4 ? box.max.z : box.min.z});
    vtkNew<vtkCellArray> lines;
    for (int i = 0; i < 8; ++i)
        for (int bit : {1, 2, 4})
            if (!(i & bit)) b.cell(lines, {id[i], id[i | bit]});
    return b.finish(nullptr, lines, nullptr);
}

Placed frustum_edges(const Frustum& f, const glm::dmat4& to_space) {
    CellBuilder b(to_space);
    std::array<vtkIdType, 8> id{};
    for (int i = 0; i < 8; ++i) id[i] = b.point(f.corners[i]);
    vtkNew<vtkCellArray> lines;
    for (int i = 0; i < 4; ++i) {
        b.cell(lines, {id[i], id[(i + 1) % 4]});          // near rectangle
        b.cell(lines, {id[4 + i], id[4 + (i + 1) % 4]});  // far rectangle
        b.cell(lines, {id[i], id[4 + i]});                // sides
    }
    return b.finish(nullptr, lines, nullptr);
}

Placed polyhedron_faces(const ConvexPolyhedron& poly, const glm::dmat4& to_space) {
    CellBuilder b(to_space);
    std::vector<vtkIdType> id;
    for (const glm::dvec3& v : poly.vertices) id.push_back(b.point(v));
    vtkNew<vtkCellArray> polys;
    for (const PolyFace& face : poly.faces) {
        std::vector<vtkIdType> loop;
        for (int i : face.loop) loop.push_back(id[i]);
        b.cell(polys, loop);
    }
    return b.finish(polys, nullptr, nullptr);
}

// A vertex at infinity (w = 0) is drawn `reach` away from its finite neighbour in the polygon, along
// its direction; a polygon with no finite vertex (a z-fail back cap) cannot be drawn.
Placed polygons_faces(const PolygonSet& set, const glm::dmat4& to_space, double reach) {
    CellBuilder b(to_space);
    vtkNew<vtkCellArray> polys;
    for (const std::vector<int>& polygon : set.polygons) {
        const size_t n = polygon.size();
        std::vector<vtkIdType> loop;
        for (size_t i = 0; i < n; ++i) {
            const glm::dvec4& v = set.vertices[polygon[i]];
            if (v.w != 0.0) {
                loop.push_back(b.point(glm::dvec3(v) / v.w));
                continue;
            }
            const glm::dvec4& before = set.vertices[polygon[(i + n - 1) % n]];
            const glm::dvec4& after = set.vertices[polygon[(i + 1) % n]];
            const glm::dvec4& anchor = before.w != 0.0 ? before : after;
            loop.push_back(anchor.w != 0.0 ? b.point(glm::dvec3(anchor) / anchor.w + reach * glm::normalize(glm::dvec3(v))) : -1);
        }
        b.cell(polys, loop);
    }
    return b.finish(polys, nullptr, nullptr);
}

// The arc as 32 straight pieces, swept in the plane of its two directions.
Placed arc_polyline(const AngleArc& arc, const glm::dmat4& to_space) {
    const glm::dvec3 a = glm::normalize(arc.from), b = glm::normalize(arc.to);
    const double angle = std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
    const glm::dvec3 across = b - glm::dot(a, b) * a;
    const glm::dvec3 side = glm::length(across) > 0.0 ? glm::normalize(across) : a;
    CellBuilder builder(to_space);
    vtkNew<vtkCellArray> lines;
    vtkIdType previous = -1;
    for (int i = 0; i <= 32; ++i) {
        const double t = angle * i / 32.0;
        const vtkIdType id = builder.point(arc.centre + arc.radius * (std::cos(t) * a + std::sin(t) * side));
        if (previous >= 0) builder.cell(lines, {previous, id});
        previous = id;
    }
    return builder.finish(nullptr, lines, nullptr);
}

}  // namespace

std::vector<glm::dvec3> object_colours(const Scene& scene) {
    static constexpr std::array<std::array<double, 3>, 6> palette{
        {{0.85, 0.62, 0.45}, {0.62, 0.71, 0.84}, {0.86, 0.80, 0.55}, {0.70, 0.82, 0.66}, {0.82, 0.66, 0.76},
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
                          const std::vector<glm::dvec3>& colours_per_object, const glm::dmat4& to_space) {
    CellBuilder b(to_space);
    std::vector<vtkIdType> id;
    id.reserve(triangles.vertices.size());
    for (const glm::dvec3& v : triangles.vertices) id.push_back(b.point(v));
    vtkNew<vtkCellArray> polys;
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetName("colour");
    colours->SetNumberOfComponents(3);
    for (size_t t = 0; t < triangles.triangles.size(); ++t) {
        const int object = triangles.object[t];
        if (!keep[object]) continue;
        const auto& tri = triangles.triangles[t];
        if (!b.cell(polys, {id[tri[0]], id[tri[1]], id[tri[2]]})) continue;
        const glm::dvec3 c = 255.0 * colours_per_object[object];
        colours->InsertNextTuple3(c.r, c.g, c.b);
    }
    Placed placed = b.finish(polys, nullptr, nullptr);
    placed.data->GetCellData()->SetScalars(colours);
    return placed;
}

Placed segments_polydata(const std::vector<std::pair<glm::dvec3, glm::dvec3>>& segments, const glm::dmat4& to_space) {
    CellBuilder b(to_space);
    vtkNew<vtkCellArray> lines;
    for (const auto& [a, c] : segments) b.cell(lines, {b.point(a), b.point(c)});
    return b.finish(nullptr, lines, nullptr);
}

Placed points_polydata(const std::vector<glm::dvec3>& points, const glm::dmat4& to_space) {
    CellBuilder b(to_space);
    vtkNew<vtkCellArray> verts;
    for (const glm::dvec3& p : points) b.cell(verts, {b.point(p)});
    return b.finish(nullptr, nullptr, verts);
}

Placed geometry_polydata(const TraceGeometry& geometry, const glm::dmat4& to_space, double reach) {
    return std::visit(
        [&](const auto& g) -> Placed {
            using G = std::decay_t<decltype(g)>;
            if constexpr (std::is_same_v<G, PointSet>) return points_polydata(g.points, to_space);
            else if constexpr (std::is_same_v<G, Aabb>) return box_edges(g, to_space);
            else if constexpr (std::is_same_v<G, ConvexPolyhedron>) return polyhedron_faces(g, to_space);
            else if constexpr (std::is_same_v<G, SegmentSet>) return segments_polydata(g.segments, to_space);
            else if constexpr (std::is_same_v<G, PolygonSet>) return polygons_faces(g, to_space, reach);
            else if constexpr (std::is_same_v<G, Arrow>) return segments_polydata({{g.from, g.to}}, to_space);
            else if constexpr (std::is_same_v<G, AngleArc>) return arc_polyline(g, to_space);
            else if constexpr (std::is_same_v<G, Label>) return points_polydata({g.at}, to_space);
            else return frustum_edges(g, to_space);
        },
        geometry);
}

}  // namespace shadowlab
