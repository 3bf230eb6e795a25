#pragma once
// A deterministic CPU depth rasterizer for shadow maps, and the shadow lookup that reads its result.
#include <vector>
#include <glm/glm.hpp>

#include "methods/method.hpp"
#include "scene/tessellation.hpp"

namespace shadowlab {

// Texel (x, y) covers u in [x, x + 1) / resolution and v in [y, y + 1) / resolution.
struct DepthMap {
    int resolution = 0;
    std::vector<float> depth;  // row-major, y * resolution + x; 1.0 where nothing was drawn

    float at(int x, int y) const { return depth[static_cast<std::size_t>(y) * resolution + x]; }
};

// The least depth d = d_pre / w of the caster triangles (objects whose flag is set) at each texel
// centre; the parts with w <= 0 or outside u, v in [0,1] are clipped away. Casters in front of
// the map's near plane (d < 0) still cast and are stored as 0, as with a clamped GPU depth range.
DepthMap rasterize_depth(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object,
                         const ShadowMap& map, int resolution);

// The nearest texel's verdict for a world point, the bias (world units along the light) applied
// before the division: d = (d_pre - z_bias_scale * bias) / w. A point with w <= 0 or u, v
// outside [0,1] is outside the map, hence lit.
bool in_shadow(const DepthMap& depth, const ShadowMap& map, const glm::dvec3& world_point, double bias);

}  // namespace shadowlab
