#pragma once
// Where a plane cuts a convex solid: the convex polygon of the points where the solid's edges cross
// the plane (an edge lying in the plane gives both its ends), ordered about the plane's normal.
#include <utility>
#include <vector>
#include <glm/glm.hpp>

#include "geometry/convex_polyhedron.hpp"
#include "geometry/frustum.hpp"
#include "geometry/plane.hpp"

namespace shadowlab {

using Edge = std::pair<glm::dvec3, glm::dvec3>;

std::vector<Edge> edges_of(const ConvexPolyhedron& solid);  // each face's loop edges (every edge twice)
std::vector<Edge> edges_of(const Frustum& frustum);         // its 12 edges

// The section of the convex solid whose edges are `edges` by `plane`: its corners counter-clockwise
// seen from the side the plane's normal points to, no corner twice; empty when the plane misses the
// solid or only touches it (fewer than 3 corners).
std::vector<glm::dvec3> plane_section(const std::vector<Edge>& edges, const Plane& plane);

}  // namespace shadowlab
