// Variance shadow maps (lookup/variance_filters.cpp): Chebyshev's bound at the receiver's depth on
// the blurred moments (d, d²).
vec4 shadowMomentsOf_vsm(float depth) { return vec4(depth, depth * depth, 0.0, 0.0); }
float shadowFilter_vsm(int i, ShadowMapReceiver m, float rotation) {
  vec4 mo = shadowSampleMoments(i, m.uv);
  float p = shadowChebyshevUpperBound(mo.x, max(mo.y - mo.x * mo.x, shadowMinVariance), m.depth);
  return shadowReduceLightBleeding(p, shadowBleedReduction);
}
