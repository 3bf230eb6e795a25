// Variance shadow maps (lookup/chebyshev.hpp): the bound's settings, EVSM's warps,
// chebyshev_upper_bound and reduce_light_bleeding.
uniform float shadowMinVariance;
uniform float shadowBleedReduction;
uniform float shadowEvsmPositive, shadowEvsmNegative;
// evsm_positive_warp and evsm_negative_warp (lookup/chebyshev.hpp): e^{c⁺d}, −e^{−c⁻d}.
vec2 shadowEvsmWarps(float depth) { return vec2(exp(shadowEvsmPositive * depth), -exp(-shadowEvsmNegative * depth)); }
// chebyshev_upper_bound and reduce_light_bleeding (lookup/chebyshev.hpp).
float shadowChebyshevUpperBound(float mean, float variance, float t) {
  if (t <= mean) return 1.0;
  float d = t - mean;
  return variance / (variance + d * d);
}
float shadowReduceLightBleeding(float pMax, float amount) {
  if (!(amount > 0.0)) return pMax;
  return clamp((pMax - amount) / (1.0 - amount), 0.0, 1.0);
}
