// Exponential shadow maps (lookup/esm_filter.cpp, lookup/exponential_shadow.hpp): the blurred
// E[e^{c z}] times e^{−c d}, clamped to 1.
uniform float shadowEsmExponent;  // c
vec4 shadowMomentsOf_esm(float depth) { return vec4(exp(shadowEsmExponent * depth), 0.0, 0.0, 0.0); }
float shadowFilter_esm(int i, ShadowMapReceiver m, float rotation) {
  return clamp(shadowSampleMoments(i, m.uv).x * exp(-shadowEsmExponent * m.depth), 0.0, 1.0);
}
