#pragma once
// Core geometry as VTK poly data, carried into a space by a homogeneous world-to-space matrix
// (points are divided by w; what lands at or behind w = 0 cannot be drawn there and is dropped).
#include <utility>
#include <vector>
#include <glm/glm.hpp>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "scene/tessellation.hpp"
#include "trace/trace.hpp"

namespace shadowlab {

struct Placed {
    vtkSmartPointer<vtkPolyData> data;
    size_t dropped = 0;  // primitives with a vertex at or behind w = 0
};

// The triangles of the objects `keep` selects (both indexed like Scene::objects), with per-cell
// RGB colours (components in [0,1]) in the array "colour".
Placed triangles_polydata(const WorldTriangles& triangles, const std::vector<bool>& keep,
                          const std::vector<glm::dvec3>& colours_per_object, const glm::dmat4& to_space);

// A muted colour per object (planes a light grey), the same in every view.
std::vector<glm::dvec3> object_colours(const Scene& scene);

// Trace geometry: boxes, frusta and segments as edges, polyhedra and polygons as faces, point sets
// as vertices. Polygon vertices at infinity are drawn `reach` world units from their finite neighbour.
Placed geometry_polydata(const TraceGeometry& geometry, const glm::dmat4& to_space, double reach = 0.0);

// Line segments, each from .first to .second.
Placed segments_polydata(const std::vector<std::pair<glm::dvec3, glm::dvec3>>& segments, const glm::dmat4& to_space);

// Points as vertices (for glyph-free point rendering).
Placed points_polydata(const std::vector<glm::dvec3>& points, const glm::dmat4& to_space);

}  // namespace shadowlab
