#pragma once
// The tessellation error of a map whose projection kind bends straight edges (issue 14; a
// paraboloid's image of a straight world edge is a circle arc): a GPU projects a triangle's vertices
// and joins them by straight edges. The kind's edge_sagitta, the image's greatest distance from the
// straight chord, is the error, in texels at a tile's resolution; splitting the casters' triangles
// until every edge's sagitta is under a target removes it.
#include <vector>
#include <glm/glm.hpp>

#include "maps/paraboloid_projection.hpp"
#include "maps/shadow_map.hpp"
#include "scene/tessellation.hpp"

namespace shadowlab {

// Texels per disc unit of a paraboloid map's tile: its diameter (2 disc units) spans the tile's
// side, tile_resolution texels.
double texels_per_disc_unit(const ShadowMap& map, int texture_resolution);

// The sagitta of the straight world edge a–b under the map (its kind's edge_sagitta) in texels of its
// tile in a texture of texture_resolution texels per side; 0 for a projective kind.
double edge_sagitta_texels(const ShadowMap& map, const glm::dvec3& a, const glm::dvec3& b, int texture_resolution);

// Whether a map's casters are split before drawing: a kind that bends edges, max_sagitta_texels > 0.
bool splits_casters(const ShadowMap& map);

// The caster triangles (objects whose flag is set) as a map that splits them draws them into its tile
// of a texture of texture_resolution texels per side: what the CPU rasterizer and the GPU pass both
// draw. Split until no edge's sagitta exceeds the map's max_sagitta_texels, each piece keeping its
// triangle's object and winding, at most 8 levels deep (kMaxSplitDepth: enough for half a texel on
// tiles up to 65536 texels). Crack-free: whether an edge splits depends on its two ends only, and its
// midpoint is one shared vertex, so the triangles on either side of an edge split it alike; the mesh
// stays watertight where the input was. Throws std::invalid_argument unless splits_casters(map).
WorldTriangles split_casters(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object,
                             const ShadowMap& map, int texture_resolution);

// The points splitting puts along the edge a–b, from a to b: the ends of the straight pieces the
// split mesh draws in its place, the same in every triangle that holds the edge.
std::vector<glm::dvec3> split_edge(const ShadowMap& map, const glm::dvec3& a, const glm::dvec3& b,
                                   int texture_resolution);

}  // namespace shadowlab
