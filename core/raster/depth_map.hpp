#pragma once
// A deterministic CPU depth rasterizer for shadow maps (lookup/shadow_reader.hpp reads its result).
// One texture holds every map of a setup, each in its tile (ShadowMap::viewport).
#include <vector>
#include <glm/glm.hpp>

#include "maps/shadow_map.hpp"
#include "scene/tessellation.hpp"

namespace shadowlab {

// The texture: texel (x, y) covers [x, x + 1) / resolution in the texture's u and [y, y + 1) /
// resolution in its v; a map's (u, v) reaches the texture through its tile (maps/map_lookup.hpp).
struct DepthMap {
    int resolution = 0;
    std::vector<float> depth;  // row-major, y * resolution + x; 1.0 where nothing was drawn

    float at(int x, int y) const { return depth[static_cast<std::size_t>(y) * resolution + x]; }
};

// Every map of the setup drawn into its tile of one resolution x resolution texture: at each texel
// centre, the least depth d = d_pre / w of the caster triangles (objects whose flag is set). The
// parts with w <= 0, outside the map's u, v in [0,1] or (a paraboloid) behind its hemisphere's plane
// are clipped away; vertices are projected one by one and joined by straight edges, as a GPU draws
// them; a paraboloid map with max_sagitta_texels > 0 draws its casters split until their straight
// edges follow the curved images (split_casters, raster/paraboloid_edges.hpp). Casters in front of a
// map's near plane (d < 0) still cast and are stored as 0, as with a clamped GPU depth range.
DepthMap rasterize_depth(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object,
                         const ShadowSetup& setup, int resolution);

}  // namespace shadowlab
