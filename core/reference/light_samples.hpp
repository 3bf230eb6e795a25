#pragma once
// Where the shadow rays of an area light go: stratified points on the unit disc (a jittered
// √N × √N grid through Shirley and Chiu's concentric map, which keeps the strata's areas equal),
// then onto the light as a point sees it: a sun's directions within its angular radius, a sphere
// light's disc facing the point. Stratified, the estimate's error falls faster than 1/√N.
#include <cstdint>
#include <vector>
#include <glm/glm.hpp>

#include "scene/light.hpp"

namespace shadowlab {

// `samples` rounded up to a square, each in its own cell of the grid, jittered by a hash of `seed`
// (deterministic: the same pixel gets the same samples).
std::vector<glm::dvec2> stratified_disc(int samples, std::uint32_t seed);

// Where a shadow ray from `p` aims for the disc sample `s`: for a sun the direction toward the
// light (unit), for a sphere light the point on the disc of radius `radius` centred on the light
// and facing p.
glm::dvec3 sun_direction(const Light& sun, const glm::dvec2& s);
glm::dvec3 sphere_light_point(const Light& light, const glm::dvec3& p, const glm::dvec2& s);

// The standard error of a visible share v estimated from n samples, √(v (1 − v) / n): the
// binomial bound, which stratified samples stay under.
double visibility_standard_error(double visibility, int samples);

}  // namespace shadowlab
