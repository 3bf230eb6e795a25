#pragma once
// What the perspective warps (PSM, LiSPSM, TSM, XPSM) share: the intersection body, the fallbacks
// taken before any warp is computed, and point sets clipped to the region that matters (for a spot
// light, the part of the body its cone reaches).
#include <optional>
#include <string>
#include <vector>

#include "geometry/intersection_body.hpp"
#include "methods/map_method.hpp"

namespace shadowlab {

// The body for a warp, or nullopt when `setup` was completed by a named fallback instead: a spot
// or point light (the warps here are for directional lights: focused map) or an empty body
// (nothing visible: uniform map).
std::optional<IntersectionBody> start_warp(const std::string& method, const ShadowInputs& inputs,
                                           const Settings& settings, ShadowSetup& setup, Trace* trace);

// start_warp for a warp of the camera's perspective (TSM, XPSM): nullopt also when the camera is
// orthographic (nothing to warp: focused map, named orthographic_camera).
std::optional<IntersectionBody> start_perspective_warp(const std::string& method, const ShadowInputs& inputs,
                                                       const Settings& settings, ShadowSetup& setup, Trace* trace);

// What a warp that handles spot and point lights (PSM, LiSPSM) covers: the body and the world points
// its map must hold, B's vertices or, for a spot light, its reach of B (spot_reach).
struct WarpRegion {
    IntersectionBody body;
    std::vector<glm::dvec3> ws_points;
};
// start_warp for such a warp: nullopt when `setup` was completed by a named fallback instead (an
// empty body: uniform map; an orthographic camera or a view the spot does not light: focused map).
std::optional<WarpRegion> start_warp_in_reach(const std::string& method, const ShadowInputs& inputs,
                                              const Settings& settings, ShadowSetup& setup, Trace* trace);

// The vertices of B cut to a pyramid circumscribing the spot's cone (only there does the spot light
// anything), the apex left out: no caster lies at the light, and a perspective map cannot hold its own
// centre. Recorded as the step spot-reach.
std::vector<glm::dvec3> spot_reach(const Light& spot, const ConvexPolyhedron& body, Trace* trace);

// The vertices of `body` within a linear map's frustum (w > 0, u and v in [0, 1]; `world_to_uvz` in the
// layout of ShadowMap), the light's position left out. A map fitted to a spot's reach takes in, through
// the corners of its (u, v) square, visible points beyond the cone; its depth range must hold these
// vertices too, or such a point falls past the far plane and reads as shadowed.
std::vector<glm::dvec3> body_within_frustum(const ConvexPolyhedron& body, const glm::dmat4& world_to_uvz,
                                            const glm::dvec3& light_position);

// The direction light travels at `p`: a directional light's, else away from the light's position.
glm::dvec3 light_ray_at(const Light& light, const glm::dvec3& p);

// Names the fallback and fits the focused map to the body.
void fall_back_to_focused(Note reason, const ShadowInputs& inputs, const IntersectionBody& body, ShadowSetup& setup,
                          Trace* trace);

// The view depths the warps read for the eye's range: what the camera can see of the receivers, as
// Filament's LiSPSM takes them (computeNearFar over the receivers' volume), never the camera's near
// and far planes, which say where the camera clips, not where anything is: a model 1,000 units away
// under a near plane at 0.05 would spend the map on the empty air before it. The camera's depth image
// where the caller measured it (ShadowInputs::visible_depths, not empty), else the receivers' boxes
// within the visible region V (their view depths, and V's, overlapped; V's alone should the boxes'
// corners all lie outside it). Within the camera's near and far either way.
DepthRange seen_receiver_depths(const ShadowInputs& inputs, const IntersectionBody& body);

// The perspective warps (psm, lispsm, tsm, xpsm): the methods a measurement holds against the
// focused map (metrics/measurement.hpp).
bool is_perspective_warp(const std::string& method);

// The depths and the strength a warp chose, as its trace recorded them ("z_n = 0.05, z_f = 655, n =
// 7.56"): what a note on a warp that loses names. Empty for a trace without them.
std::string warp_choices(const Trace& trace);

// Corners of each box cut to `region` (boxes that miss it give none).
std::vector<glm::dvec3> corners_within(const std::vector<Aabb>& boxes, const Aabb& region);

// Points through a projective matrix, divided by w; points with w < min_w are left out.
struct ProjectedPoints {
    std::vector<glm::dvec3> points;
    size_t left_out = 0;
};
ProjectedPoints project(const std::vector<glm::dvec3>& points, const glm::dmat4& m, double min_w);

}  // namespace shadowlab
