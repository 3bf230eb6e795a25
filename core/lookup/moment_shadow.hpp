#pragma once
// Moment shadow maps (Peters and Klein, "Moment Shadow Mapping", I3D 2015): a texel stores four
// moments b = (E[z], E[z²], E[z³], E[z⁴]) of the depths under the filter, and the lookup computes
// the sharpest lower bound on the share of them nearer the light than the receiver that any
// distribution with those moments allows (the Hamburger moment problem, four moments). Unlike
// Chebyshev's bound on two moments (VSM), a receiver behind two casters at different depths is
// bounded to darkness: no light bleeds there.
#include <glm/glm.hpp>

namespace shadowlab {

// The moments of one depth z in [0, 1]: (z, z², z³, z⁴).
glm::dvec4 power_moments(double depth);

// Peters and Klein's Algorithm 3 (Hamburger 4MSM): the shadow intensity G in [0, 1] (the share of
// the depths below `depth`; visibility is 1 − G) from the moments b, after the moment bias pulls b
// by `moment_bias` (α) toward the moments of three depths, so that the Hankel matrix stays positive
// definite when rounding (or a single depth) would make it singular.
double hamburger_shadow_intensity(const glm::dvec4& moments, double depth, double moment_bias);

// The optimized 16-bit quantization (Peters and Klein 2015, Section 4.2 and supplementary listing 1,
// for depths in [0, 1]): an affine change of basis under which the moments of every depth in [0, 1]
// lie in [0, 1]⁴ and round to 16 bits with the least error. Linear, so it commutes with the blur.
glm::dvec4 optimized_moments(const glm::dvec4& power);         // b ↦ the quantized basis
glm::dvec4 power_from_optimized(const glm::dvec4& optimized);  // its inverse
// Each of the four rounded to the nearest of 2^16 − 1 steps in [0, 1] (an RGBA16_UNORM texel).
glm::dvec4 rounded_to_unorm16(const glm::dvec4& value);

}  // namespace shadowlab
