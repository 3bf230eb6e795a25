#pragma once
// The exact depth picture of a paraboloid map, for judging what the rasterizer draws: no vertex is
// projected and no edge drawn straight; each texel's own direction is traced.
#include <vector>

#include "maps/shadow_map.hpp"
#include "raster/depth_map.hpp"
#include "scene/tessellation.hpp"

namespace shadowlab {

// Every map of the setup in its tile, as rasterize_depth lays them out: at each texel centre inside
// a paraboloid's disc, the depth (|q| - near) / (far - near) of the first caster the ray from the
// map's centre along that texel's direction meets (disc (x, y) -> (2x, 2y, 1 - x² - y²) / (1 + x² +
// y²) in the map's frame), clamped to [0, 1] and stored as float32 (the default DepthFormat) as the rasterizer stores
// it; 1 outside the disc and where the ray meets nothing. Traced relative to the centre, so that Embree's float32 is as
// fine there as anywhere. Throws std::invalid_argument for a map that is not a paraboloid.
DepthMap traced_depth_map(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object,
                          const ShadowSetup& setup, int resolution);

}  // namespace shadowlab
