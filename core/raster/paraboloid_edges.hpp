#pragma once
// The tessellation error of a paraboloid map (issue 14): a GPU projects a triangle's vertices and
// joins them by straight edges, while the paraboloid's true image of a straight world edge is a
// circle arc. Its sagitta, the arc's greatest distance from the straight chord, is the error, in
// disc units here and in texels at a tile's resolution; splitting the casters' triangles until every
// edge's sagitta is under a target removes it.
#include <vector>
#include <glm/glm.hpp>

#include "maps/shadow_map.hpp"
#include "scene/tessellation.hpp"

namespace shadowlab {

// The disc: the paraboloid's image plane, (u, v) = (disc + 1) / 2. A unit direction d in the map's
// frame lands at (d.x, d.y) / (1 + d.z); the hemisphere d.z >= 0 fills the unit disc.
glm::dvec2 disc_of(const glm::dvec3& direction);
// The inverse: the unit direction the disc point (x, y) sees, (2x, 2y, 1 - x² - y²) / (1 + x² + y²).
glm::dvec3 direction_of(const glm::dvec2& disc);

// Texels per disc unit of a paraboloid map's tile: its diameter (2 disc units) spans the tile's
// side, tile_resolution texels.
double texels_per_disc_unit(const ShadowMap& map, int texture_resolution);

// How far (disc units) the image of the straight world edge a–b bows from the chord a GPU draws
// between its projected ends, in closed form (see the .cpp). Only the map's side of the hemisphere's
// plane is drawn: an edge behind it gives 0; an edge crossing it, cut as the rasterizer cuts it,
// gives the sagitta of its part in front plus how far the cut of the drawn chord lies from the arc's
// true end on the rim (a bound on the distance between the drawn and the true image). Symmetric in
// a and b to the last bit, so that the two triangles sharing an edge agree on it.
double edge_sagitta(const Paraboloid& paraboloid, const glm::dvec3& a, const glm::dvec3& b);

// The triangles split until no edge's sagitta exceeds max_sagitta_texels (at texels_per_unit), each
// piece keeping its triangle's object and winding, at most 8 levels deep (kMaxSplitDepth: enough for
// half a texel on tiles up to 65536 texels). Crack-free: whether an edge splits depends on its two
// ends only, and its midpoint is one shared vertex, so the triangles on either side of an edge split
// it alike; the mesh stays watertight where the input was. Throws std::invalid_argument unless both
// numbers are > 0.
WorldTriangles split_for_paraboloid(const WorldTriangles& triangles, const Paraboloid& paraboloid,
                                    double texels_per_unit, double max_sagitta_texels);

// The points splitting puts along the edge a–b, from a to b: the ends of the straight pieces the
// split mesh draws in its place, the same in every triangle that holds the edge.
std::vector<glm::dvec3> split_edge(const Paraboloid& paraboloid, const glm::dvec3& a, const glm::dvec3& b,
                                   double texels_per_unit, double max_sagitta_texels);

// Whether a map's casters are split before drawing: a paraboloid with max_sagitta_texels > 0.
bool splits_casters(const ShadowMap& map);

// The caster triangles (objects whose flag is set) as a map that splits them draws them into its tile
// of a texture of texture_resolution texels per side: what the CPU rasterizer and the GPU pass both draw.
WorldTriangles split_casters(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object,
                             const ShadowMap& map, int texture_resolution);

}  // namespace shadowlab
