#pragma once
// Percentage-closer soft shadows (Fernando 2005), the geometry of its steps: the penumbra an area
// light casts past a blocker, which sizes both the blocker search and the filter.
#include <glm/glm.hpp>

#include "scene/light.hpp"

namespace shadowlab {

// PCSS step 2: the penumbra's width on a receiver, w = (d_r − d_b) · w_light / d_b, the distances
// d_r (receiver) and d_b (blocker) from a light w_light wide, along the light, parallel planes.
double penumbra_width(double receiver_distance, double blocker_distance, double light_width);

// The same for the scene's light at receiver point p and a blocker `delta` world units before p
// toward the light: a sphere light of radius R at distance L gives (L − (L − Δ)) 2R / (L − Δ); a sun
// of angular radius α, the limit of far lights, 2 Δ tan α. 0 for a light without size; infinite
// when the blocker reaches the light.
double penumbra_width(const Light& light, const glm::dvec3& p, double delta);

// PCSS step 1's footprint: a blocker `delta` before p can hide part of the light only within half
// the penumbra it would cast, penumbra_width(light, p, delta) / 2, of p's place across the light.
double blocker_search_radius(const Light& light, const glm::dvec3& p, double delta);

}  // namespace shadowlab
