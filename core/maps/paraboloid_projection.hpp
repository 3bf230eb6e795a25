#pragma once
// The paraboloid projection kind: one hemisphere of a dual-paraboloid map (Brabec, Annen and Seidel
// 2002). A world point p seen from the centre in the hemisphere's frame, q = frame_from_world (p -
// centre), d = q / |q|, lands on the disc at (d.x, d.y) / (1 + d.z), its (u, v) = (disc + 1) / 2, at
// depth (|q| - near) / (far - near). Its casters are cut at the hemisphere's plane q.z = 0, and the
// image of a straight edge is a circle arc: edge_sagitta measures it in closed form.
#include <glm/glm.hpp>

#include "maps/projection_kind.hpp"

namespace shadowlab {

extern const ProjectionKind paraboloid_projection;

// The disc: the paraboloid's image plane, (u, v) = (disc + 1) / 2. A unit direction d in the map's
// frame lands at (d.x, d.y) / (1 + d.z); the hemisphere d.z >= 0 fills the unit disc.
glm::dvec2 disc_of(const glm::dvec3& direction);
// The inverse: the unit direction the disc point (x, y) sees, (2x, 2y, 1 - x² - y²) / (1 + x² + y²).
glm::dvec3 direction_of(const glm::dvec2& disc);

// How far (disc units) the image of the straight world edge a–b bows from the chord a GPU draws
// between its projected ends, in closed form (see the .cpp). Only the map's side of the hemisphere's
// plane is drawn: an edge behind it gives 0; an edge crossing it, cut as the rasterizer cuts it,
// gives the sagitta of its part in front plus how far the cut of the drawn chord lies from the arc's
// true end on the rim (a bound on the distance between the drawn and the true image). Symmetric in
// a and b to the last bit, so that the two triangles sharing an edge agree on it.
double edge_sagitta(const Paraboloid& paraboloid, const glm::dvec3& a, const glm::dvec3& b);

}  // namespace shadowlab
