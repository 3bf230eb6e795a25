#pragma once
// The one CPU lookup of a shadow setup: world point -> its map, (u, v), depth with the bias, and the
// texel of the texture (atlas) it reads. The rasterizer, the metrics, the views and the exports use
// it; the GPU pass (viewer/render/shadow_map_pass.cpp) mirrors it line by line.
#include <optional>
#include <glm/glm.hpp>

#include "geometry/frustum.hpp"
#include "maps/shadow_map.hpp"

namespace shadowlab {

// The point under one map before the division: (u w, v w, d_pre, w) for linear maps and cube faces;
// (u, v, d, 1) for a paraboloid (w = 0 at the point straight behind it, where the map is singular).
glm::dvec4 map_homogeneous(const ShadowMap& map, const glm::dvec3& world);

// The map with its depth reversed, s = 1 − d, from its kind's own terms (ProjectionKind::reversed_depth):
// what a reversed-Z depth format draws with.
ShadowMap with_reversed_depth(const ShadowMap& map);

// (u, v, d) of a world point under one map, after the division by w.
glm::dvec3 world_to_uvz(const ShadowMap& map, const glm::dvec3& world);

// The signed distance of a world point to the plane the map's kind clips its casters at (>= 0: its
// side; a paraboloid's hemisphere plane, ProjectionKind::clip_distance); +1 for kinds with no such plane.
double hemisphere_side(const ShadowMap& map, const glm::dvec3& world);

// The index of the map the setup's selection rule gives the point, or -1 when none does (lit).
int select_map(const ShadowSetup& setup, const glm::dvec3& world);

// The crossfade of a view_depth selection with a blend band: over the last blend_band of its split
// (the band's width blend_band × (split_depths[i + 1] − split_depths[i])), map i fades into map i + 1,
// the weight rising linearly from 0 where the band starts to 1 at the split's far end. The last
// split has no next map and no band; the other rules never blend.
struct MapBlend {
    int map = -1;         // select_map's: the point's own map, -1 for none
    int next = -1;        // the map it fades into, -1 outside a band
    double weight = 0.0;  // next's share of the verdict, in (0, 1] inside a band
};
MapBlend blend_of(const ShadowSetup& setup, const glm::dvec3& world);

// The world region a map of a projective kind (ProjectionKind::projective: a linear map, a cube face)
// covers: its unit cube [0,1]^3 taken back through world_to_uvz (near face d = 0 first). Other kinds
// have no such box.
Frustum map_volume(const ShadowMap& map);

// Map texels per side of one map's tile in a texture of `texture_resolution` texels per side.
double tile_resolution(const ShadowMap& map, int texture_resolution);

// Where a map's (u, v) lies in the texture, and the texel it reads there (nearest, kept in the tile).
glm::dvec2 texture_uv(const ShadowMap& map, const glm::dvec2& uv);
glm::ivec2 texel_of(const ShadowMap& map, const glm::dvec2& uv, int texture_resolution);

// A point under the map the selection gives it, before the division: nullopt when no map is
// selected or the point lies behind the map's centre (w <= 0). (u, v, d) may fall outside [0,1].
struct MapPoint {
    int map = -1;
    glm::dvec4 homogeneous;  // map_homogeneous(maps[map], p)

    glm::dvec3 uvz() const { return glm::dvec3(homogeneous) / homogeneous.w; }
};
std::optional<MapPoint> map_point(const ShadowSetup& setup, const glm::dvec3& world);

struct MapLookup {
    int map = -1;        // which map
    glm::dvec2 uv;       // in that map, [0,1]
    double depth = 0.0;  // (d_pre - z_bias_scale * bias) / w
};

// The point's map, (u, v) and biased depth (bias in world units along the light); nullopt where no
// map covers it (behind a map's centre, outside its [0,1] square, or no map selected): lit.
std::optional<MapLookup> look_up(const ShadowSetup& setup, const glm::dvec3& world, double bias);
// The same under a given map of the setup (a blend's next map); nullopt for map -1.
std::optional<MapLookup> look_up_in(const ShadowSetup& setup, int map, const glm::dvec3& world, double bias);

// How (u, v) moves per world unit along `direction` at p under one map, by its kind: exact for linear
// maps and cube faces (the quotient rule on the matrix rows), a central difference sized by the
// distance to the centre for a paraboloid; no step tied to the scene's extent or position.
glm::dvec2 uv_derivative(const ShadowMap& map, const glm::dvec3& p, const glm::dvec3& direction);

// The same setup for points given relative to `origin` (p - origin): what a float32 consumer (the GPU
// passes) draws with near the camera, however far the scene stands from the world's origin.
ShadowSetup relative_to(ShadowSetup setup, const glm::dvec3& origin);

// ∂d/∂t: the map's depth (after the division) per world unit along `direction` at p. Exact for
// linear maps and cube faces (the quotient rule on the matrix rows) and for paraboloids (d grows
// with the distance to the centre).
double depth_slope(const ShadowMap& map, const glm::dvec3& direction, const glm::dvec3& p);

// How far from p back toward the light (against `direction`, the way light travels) the map's depth
// falls to `depth`: exact for every projection (a linear map's depth is a linear fraction of the
// distance along a ray, a paraboloid's linear in it). Infinite where the ray never reaches it.
double distance_back_to_depth(const ShadowMap& map, const glm::dvec3& direction, const glm::dvec3& p, double depth);

// World units along the light per unit at p under one map: 1 / (dd / dt), d the
// divided depth, t the distance along `light_direction`.
double world_per_depth_unit(const ShadowMap& map, const glm::dvec3& light_direction, const glm::dvec3& p);

}  // namespace shadowlab
