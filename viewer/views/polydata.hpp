#pragma once
// Core geometry as VTK poly data, carried into a space by a homogeneous world-to-space matrix and cut
// there, before the division by w, to w > 0, to an optional box and to further half-spaces: a line
// through w = 0 stops at the box instead of running off to infinity.
#include <optional>
#include <utility>
#include <vector>
#include <glm/glm.hpp>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "geometry/homogeneous_clip.hpp"
#include "scene/tessellation.hpp"
#include "trace/trace.hpp"

namespace shadowlab {

struct Placed {
    vtkSmartPointer<vtkPolyData> data;
    size_t dropped = 0;  // primitives of which nothing is left in front of w = 0 and inside the box
};

// How shapes are carried into a space.
struct Placement {
    glm::dmat4 to_space{1.0};    // world -> space, homogeneous
    std::optional<Aabb> clip;    // the box of the space the shapes are cut to; none: only to w > 0
    std::vector<ClipPlane> cut;  // half-spaces of the space's (x, y, z, w) the shapes are cut to besides (a map's mask)
    double reach = 0.0;          // world units a polygon's vertex at infinity is drawn from its finite neighbour
    double head = 0.0;           // an arrow head's length in space units; 0: a quarter of the arrow
};

// A world point in the space: nullopt at or behind w = 0 or outside the clip box.
std::optional<glm::dvec3> placed_point(const Placement& placement, const glm::dvec3& world);

// The triangles of the objects `keep` selects (both indexed like Scene::objects), with per-cell
// RGB colours (components in [0,1]) in the array "colour".
Placed triangles_polydata(const WorldTriangles& triangles, const std::vector<bool>& keep,
                          const std::vector<glm::dvec3>& colours_per_object, const Placement& placement);

// A muted colour per object (planes a light grey), the same in every view.
std::vector<glm::dvec3> object_colours(const Scene& scene);

// Trace geometry: boxes, frusta, segments and angle arcs as edges, polyhedra and polygons as faces,
// point sets as vertices, arrows as a shaft and a cone at the tip, a label as the dot it names
// (its text is the view's: views/space_canvas.cpp).
Placed geometry_polydata(const TraceGeometry& geometry, const Placement& placement);

// The edges of the faces of a polyhedron or a polygon set (nullopt for other shapes): a translucent
// face's outline, crisp in its colour.
std::optional<Placed> outline_polydata(const TraceGeometry& geometry, const Placement& placement);

// Line segments, each from .first to .second.
Placed segments_polydata(const std::vector<std::pair<glm::dvec3, glm::dvec3>>& segments, const Placement& placement);
// Many boxes' edges in one polydata (one actor: a town's hundreds of boxes draw at once).
Placed boxes_polydata(const std::vector<Aabb>& boxes, const Placement& placement);

// Points as vertices (for glyph-free point rendering).
Placed points_polydata(const std::vector<glm::dvec3>& points, const Placement& placement);

// The same, carried by a matrix alone (cut only to w > 0).
inline Placed triangles_polydata(const WorldTriangles& triangles, const std::vector<bool>& keep,
                                 const std::vector<glm::dvec3>& colours_per_object, const glm::dmat4& to_space) {
    return triangles_polydata(triangles, keep, colours_per_object, Placement{.to_space = to_space});
}
inline Placed geometry_polydata(const TraceGeometry& geometry, const glm::dmat4& to_space) {
    return geometry_polydata(geometry, Placement{.to_space = to_space});
}
inline Placed segments_polydata(const std::vector<std::pair<glm::dvec3, glm::dvec3>>& segments,
                                const glm::dmat4& to_space) {
    return segments_polydata(segments, Placement{.to_space = to_space});
}

}  // namespace shadowlab
