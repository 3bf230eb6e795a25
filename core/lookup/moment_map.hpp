#pragma once
// The prefiltered texture VSM, EVSM, MSM and ESM read: per texel the moments of its depth (the
// filter's MomentEncoding), blurred by an N×N box within each map's tile (the blur never mixes two
// maps), kept as the filter stores them, then read bilinearly. A float32 texture, as a GPU's RGBA32F
// would hold it (msm's 16-bit variant: values a GPU's RGBA16_UNORM would hold).
#include <vector>
#include <glm/glm.hpp>

#include "lookup/shadow_filter.hpp"
#include "maps/shadow_map.hpp"
#include "raster/depth_map.hpp"

namespace shadowlab {

struct MomentMap {
    int resolution = 0;
    // vsm: (d, d², 0, 0); evsm: (e⁺, (e⁺)², e⁻, (e⁻)²), e⁺ = e^{c⁺d}, e⁻ = −e^{−c⁻d};
    // msm: (d, d², d³, d⁴), or their optimized 16-bit basis; esm: (e^{cd}, 0, 0, 0)
    std::vector<glm::vec4> moments;

    const glm::vec4& at(int x, int y) const { return moments[static_cast<std::size_t>(y) * resolution + x]; }
};

// The depth texture's moments for `filter` (one that reads moments), each map's tile box-blurred over
// filter.kernel_size texels per side (centred; an even side reaches one texel further toward -u, -v),
// edges clamped to the tile.
MomentMap blurred_moments(const DepthMap& depth, const ShadowSetup& setup, const ShadowFilter& filter);

// The moments at a map's (u, v): bilinear between the four nearest texel centres, kept in the map's tile.
glm::dvec4 sample_moments(const MomentMap& moments, const ShadowMap& map, const glm::dvec2& uv);

}  // namespace shadowlab
