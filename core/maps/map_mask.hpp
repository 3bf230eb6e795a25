#pragma once
// A map's mask (ShadowMap::mask): the part of its (u, v) square its casters are drawn in, the square
// cut by half-planes a u + b v + c >= 0. Several maps then share one texture, each in its own
// region, as a tetrahedron's four faces share one square (Liao 2010, drawn there through a stencil):
// the rasterizer clips a map's casters by its mask, the GPU pass by clip distances, and the views
// draw its outline. A half-plane is linear in the homogeneous (u w, v w, d_pre, w) as well, so the
// casters are cut before the division, exactly.
#include <vector>
#include <glm/glm.hpp>

#include "geometry/homogeneous_clip.hpp"
#include "maps/shadow_map.hpp"

namespace shadowlab {

// The half-plane a u + b v + c >= 0 holding the points left of the directed segment from -> to (a
// counter-clockwise polygon's inside along its edge).
glm::dvec3 left_of(const glm::dvec2& from, const glm::dvec2& to);

// Whether (u, v) lies in the map's mask (every point of a map without one).
bool in_mask(const ShadowMap& map, const glm::dvec2& uv);

// The mask's half-planes as clip planes of the map's homogeneous (u w, v w, d_pre, w).
std::vector<ClipPlane> mask_clip_planes(const ShadowMap& map);

// The map's region of its square: the unit square cut by the mask, counter-clockwise in (u, v).
std::vector<glm::dvec2> mask_outline(const ShadowMap& map);

// The share of its square the map's region holds: 1 without a mask, 1/4 for a tetrahedron's face.
double mask_area(const ShadowMap& map);

}  // namespace shadowlab
