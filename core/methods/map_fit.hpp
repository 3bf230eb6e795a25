#pragma once
// Fitting one map to a set of world points for any light type, with its trace steps: the
// orthographic fit in light space for a directional light, the perspective fit for spot and point.
#include <vector>
#include <glm/glm.hpp>

#include "methods/map_method.hpp"

namespace shadowlab {

struct MapFitRequest {
    const std::vector<glm::dvec3>* points;  // world points the map must cover
    glm::dvec3 up_hint;                     // directional: the light space's y is this, made perpendicular
    glm::dvec3 aim;                         // point light: a world point to aim the map at
};

// Appends the fitted map to `setup` (and a named fallback when the light cannot cover the points).
void fit_map(const ShadowInputs& inputs, const MapFitRequest& request, ShadowSetup& setup, Trace* trace);

// Records the final step: each map's matrix and bias scale, and the covered points in unit space.
void record_output(const ShadowSetup& setup, const std::vector<glm::dvec3>& covered, Trace* trace);

// Adds a named fallback to the setup.
void add_fallback(ShadowSetup& setup, Note fallback);

}  // namespace shadowlab
