#pragma once
// The depth biases a lookup can apply, all of them settings of every map method: what keeps a lit
// surface from shadowing itself (acne) without lifting shadows off their casters (peter panning).
// Every bias is a world length along the light: the depth compared is the map's depth of the point
// moved that far toward the light, exact whatever the map's perspective (a pre-division offset, as
// XPSM's step 18 has it, shrinks by w and grows z/n-fold where a perspective map's depth is steep).
#include <string>
#include <glm/glm.hpp>

#include "maps/shadow_map.hpp"

namespace shadowlab {

struct DepthBias {
    double constant = 0.0;        // world units along the light
    double slope_scale = 1.0;     // times slope_scaled_bias
    double normal_offset = 0.0;   // texels: the lookup point moved off the surface along its normal by this
                                  // many texel widths (Holbert 2011), which needs less depth bias at grazing light
    bool receiver_plane = false;  // each texel read compares with the receiver's plane at that texel's centre
                                  // (Isidoro 2006), not with the depth at the point: no acne within a plane
};

// "slope-scaled ×1", "constant 0.05 + normal offset 1.5 texels + receiver plane", "none".
std::string describe(const DepthBias& bias);

// The bias a texel needs at p, as engines' slope-scaled bias: the texel's world size across the
// light times (1 + tan θ), θ between the surface and the light (tan clamped to 10), so that the
// surface within one texel never rises above its own stored depth. `texels` across the map's tile
// (tile_resolution).
double slope_scaled_bias(const ShadowMap& map, double texels, const glm::dvec3& light_direction, const glm::dvec3& p,
                         double cos_theta);
// The same from a texel's world width already known: texel_world × (1 + min(tan θ, 10)).
double slope_scaled_bias(double texel_world, double cos_theta);

// The world width across the light of one texel of the map at p (its longest extent).
double texel_world_size(const ShadowMap& map, double texels, const glm::dvec3& light_direction, const glm::dvec3& p);

// The receiver's plane in the map: ∂d/∂(u, v) on the plane through p with normal n (first order on
// a perspective map), so that the plane's depth at (u, v) + Δ is d + Δ · gradient. Zero where the
// plane is edge-on to the light (the map sees it as a line: no gradient exists).
glm::dvec2 receiver_plane_gradient(const ShadowMap& map, const glm::dvec3& p, const glm::dvec3& normal);

}  // namespace shadowlab
