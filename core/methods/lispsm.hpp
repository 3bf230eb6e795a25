#pragma once
#include <string>
#include <vector>

#include "geometry/aabb.hpp"
#include "methods/map_method.hpp"
#include "methods/warp_common.hpp"

namespace shadowlab {

ShadowSetup compute_lispsm(const ShadowInputs& inputs, const Settings& settings, Trace* trace);
// lispsm's settings, with their ranges and defaults.
std::vector<SettingSpec> lispsm_settings();
// depths = image: the eye's range is read off the camera's depth image (ShadowInputs::visible_depths).
bool lispsm_reads_visible_depths(const Settings& settings);

// The warp frustum's near distance n for the eye range [z_n, z_f] and angle γ between view and
// light, with Lloyd's η: the warp's far/near ratio is (z_f / z_n)^((1 + η) / 2), so η = -1 gives
// no warp (n = ∞), η = 0 LiSPSM's n_opt = (z_n + sqrt(z_n z_f)) / sin γ, η = 1 PSM's n = z_n / sin γ.
double lispsm_n(double z_n, double z_f, double sin_gamma, double eta);

// What LiSPSM warps: a body (world points, or points of a spot light's post-perspective space, where
// its rays are parallel) seen by an eye whose view range starts at z_n, under a directional light.
// `z_f`, when positive, is the eye's depth of the body's far end (else z_n + depth(B) sin γ, as for a
// directional light in the world); `n` overrides n_opt when positive.
struct LispsmRequest {
    const std::vector<glm::dvec3>* ws_body;
    glm::dvec3 eye, view_direction, light_direction;
    double z_n = 0.0, eta = 0.0, n = 0.0, z_f = 0.0;
};

// LiSPSM's construction for one body, each quantity its steps show; `warps` is false when the warp
// has faded to nothing (then only the light space, γ and n are set). Cascades warp each split with it.
struct LispsmWarp {
    glm::dmat4 light_from_world{1.0};
    std::vector<glm::dvec3> ls_body;
    Aabb ls_body_box;
    double sin_gamma = 0.0, z_f = 0.0, n = 0.0, depth = 0.0;
    glm::dvec3 ls_eye{0.0}, ls_near_face{0.0}, ls_centre{0.0};
    bool warps = false;
    glm::dmat4 ppls_from_light{1.0}, uvz_from_ppls{1.0};
    ProjectedPoints ppls_body;
    Aabb ppls_box;
    ShadowMap map;  // uvz_from_ppls * ppls_from_light * light_from_world
};
LispsmWarp lispsm_warp(const LispsmRequest& request);

// LiSPSM's first steps, shared by the warps built on it: light-space (B in light space; the light
// frame set to light_from_world * space_from_world) and gamma (V, L and the angle between them, the
// view's arrow named `view_name`).
void record_light_space(Trace& t, const LispsmWarp& warp, const glm::dmat4& space_from_world,
                        const glm::dvec3& view_direction, const glm::dvec3& light_direction,
                        const std::string& view_name);
// The steps warp-frustum (the frustum P in light space) and warp (B in PPLS; the ppls frame set).
void record_warp(Trace& t, const LispsmWarp& warp, const glm::dmat4& space_from_world);

// The warp frustum P (the warped body's box taken back into light space, looking along +y from C),
// drawn with its centre, near and far distances.
void draw_warp_frustum(Step& step, const LispsmWarp& warp);

}  // namespace shadowlab
