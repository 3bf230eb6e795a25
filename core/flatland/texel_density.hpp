#pragma once
// How finely a setup samples the view axis: texels per unit of view depth along the view, against
// the ideal density, at which the perspective factor of Lloyd's m is 1 (Lloyd, Govindaraju,
// Quammen, Molnar and Manocha 2008, "Logarithmic perspective shadow maps", plot exactly these:
// uniform flat, a perspective warp between, the ideal falling as 1/z).
#include <optional>
#include <vector>
#include <glm/glm.hpp>

#include "maps/shadow_map.hpp"
#include "methods/shadow_inputs.hpp"

namespace shadowlab {

struct DensitySample {
    double depth = 0.0;        // z: the point eye + z V
    int map = -1;              // the map the selection gives it
    glm::dvec2 per_axis{0.0};  // texel boundaries of u and of v crossed per unit of z: R |∂u/∂z|, R |∂v/∂z|
    double texels = 0.0;       // R |∂(u, v)/∂z|: texels per unit of view depth
    double ideal = 0.0;        // ideal_texel_density at z
};

// Where the view axis runs through the visible part of the scene: inside the camera's near and far
// planes and the scene's bounds; nullopt when it misses them.
struct DepthSpan {
    double near = 0.0, far = 0.0;
};
std::optional<DepthSpan> view_axis_span(const ShadowInputs& inputs);

// `count` depths from near to far, evenly spaced on a log scale (the ideal a straight line there).
std::vector<double> log_spaced_depths(const DepthSpan& span, int count);

// The ideal density at view depth z for an image `image_height` pixels tall. A pixel at depth z
// covers 2 h(z) / H across the view, h(z) the camera's half height there (z tan(θ/2) for a pinhole,
// Camera::half_extent_at). Lloyd's perspective factor of m is a texel's length along the view,
// 1 / ρ(z), over that footprint: m_p(z) = (1 / ρ(z)) / (2 h(z) / H) (the projection factor, the
// surfaces' slopes to the light and the eye, set apart as Lloyd sets it apart). m_p = 1 at every z
// when ρ(z) = H / (2 h(z)) = H / (2 z tan(θ/2)): proportional to 1/z for a pinhole, whose integral
// from n to z, (H / (2 tan(θ/2))) ln(z / n), is the logarithmic parameterization LogPSM approaches;
// constant for an orthographic camera.
double ideal_texel_density(const Camera& camera, int image_height, double depth);

// The setup's density at each depth along the view axis, through each map's kind's derivative
// (maps/map_lookup.hpp uv_derivative); a depth where no map holds the point in its unit cube is left out.
std::vector<DensitySample> texel_density_along_view(const ShadowSetup& setup, const Camera& camera,
                                                    int texture_resolution, int image_height,
                                                    const std::vector<double>& depths);

// The density at kDensityDepths depths log-spaced over view_axis_span: what the Plot dock and `lesson`
// chart; empty when the view axis misses the scene.
constexpr int kDensityDepths = 64;
std::vector<DensitySample> texel_density_over_view(const ShadowInputs& inputs, const ShadowSetup& setup,
                                                   int texture_resolution, int image_height);

}  // namespace shadowlab
