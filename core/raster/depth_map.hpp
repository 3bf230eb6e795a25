#pragma once
// A deterministic CPU depth rasterizer for shadow maps (lookup/shadow_reader.hpp reads its result).
// One texture holds every map of a setup, each in its tile (ShadowMap::viewport).
#include <vector>
#include <glm/glm.hpp>

#include "maps/shadow_map.hpp"
#include "raster/depth_format.hpp"
#include "scene/tessellation.hpp"

namespace shadowlab {

// The texture: texel (x, y) covers [x, x + 1) / resolution in the texture's u and [y, y + 1) /
// resolution in its v; a map's (u, v) reaches the texture through its tile (maps/map_lookup.hpp).
// Each texel holds its depth as the map's format stores it (raster/depth_format.hpp): every reader
// reads it back as d through at(), the depth the format kept, exact in double.
struct DepthMap {
    int resolution = 0;
    DepthFormat format;
    std::vector<DepthCode> codes;  // row-major, y * resolution + x; far_code (d = 1) where nothing was drawn

    DepthMap() = default;
    // resolution x resolution texels of the format, nothing drawn.
    DepthMap(int resolution, const DepthFormat& format);

    double at(int x, int y) const { return DepthDecoder(format)(codes[index(x, y)]); }
    // Stores d at a texel as the format does (stored_depth).
    void set(int x, int y, double depth);
    std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * resolution + x; }
};

// Every map of the setup drawn into its tile of one resolution x resolution texture: at each texel
// centre, the depth d = d_pre / w of the nearest caster triangle (objects whose flag is set) as
// `format` stores it: the least d, reversed the greatest s = (w − d_pre) / w, interpolated from
// each map's own reversed depth (with_reversed_depth: no 1 − d after the division). The parts with
// w <= 0, outside the map's u, v in [0,1] or (a paraboloid) behind its hemisphere's plane are
// clipped away; vertices are projected one by one and joined by straight edges, as a GPU draws
// them; a paraboloid map with max_sagitta_texels > 0 draws its casters split until their straight
// edges follow the curved images (split_casters, raster/paraboloid_edges.hpp). Casters in front of a
// map's near plane (d < 0) still cast and are stored as 0, as with a clamped GPU depth range; beyond
// its far plane a unorm or a reversed map stores 1 (as far as nothing), plain float32 the depth.
DepthMap rasterize_depth(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object,
                         const ShadowSetup& setup, int resolution, const DepthFormat& format = {});

}  // namespace shadowlab
