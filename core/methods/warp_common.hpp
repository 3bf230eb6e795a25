#pragma once
// What the perspective warps (PSM, LiSPSM, TSM, XPSM) share: the intersection body, the fallbacks
// taken before any warp is computed, and point sets clipped to the region that matters.
#include <optional>
#include <vector>

#include "geometry/intersection_body.hpp"
#include "methods/map_method.hpp"

namespace shadowlab {

// The body for a warp, or nullopt when `setup` was completed by a named fallback instead: a spot
// or point light (the warps here are for directional lights: focused map) or an empty body
// (nothing visible: uniform map).
std::optional<IntersectionBody> start_warp(const std::string& method, const ShadowInputs& inputs,
                                           const Settings& settings, ShadowSetup& setup, Trace* trace);

// Names the fallback and fits the focused map to the body.
void fall_back_to_focused(Note reason, const ShadowInputs& inputs, const IntersectionBody& body,
                          ShadowSetup& setup, Trace* trace);

// Corners of each box cut to `region` (boxes that miss it give none).
std::vector<glm::dvec3> corners_within(const std::vector<Aabb>& boxes, const Aabb& region);

// Points through a projective matrix, divided by w; points with w < min_w are left out.
struct ProjectedPoints {
    std::vector<glm::dvec3> points;
    size_t left_out = 0;
};
ProjectedPoints project(const std::vector<glm::dvec3>& points, const glm::dmat4& m, double min_w);

}  // namespace shadowlab
