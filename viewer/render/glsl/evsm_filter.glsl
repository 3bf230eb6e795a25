// Exponential variance shadow maps (lookup/variance_filters.cpp): the tighter of Chebyshev's bounds
// on the two warps' moments, the variance floors scaled by each warp's slope, (c e^{cd})², so that
// they are the same in depth units.
// exponential_moments: each warp and its square, (e⁺, (e⁺)², e⁻, (e⁻)²).
vec4 shadowMomentsOf_evsm(float depth) {
  vec2 e = shadowEvsmWarps(depth);
  return vec4(e.x, e.x * e.x, e.y, e.y * e.y);
}
float shadowFilter_evsm(int i, ShadowMapReceiver m, float rotation) {
  vec4 mo = shadowSampleMoments(i, m.uv);
  vec2 e = shadowEvsmWarps(m.depth);
  vec2 slopes = vec2(shadowEvsmPositive, shadowEvsmNegative) * e;
  vec2 floors = shadowMinVariance * slopes * slopes;
  float p = min(shadowChebyshevUpperBound(mo.x, max(mo.y - mo.x * mo.x, floors.x), e.x),
                shadowChebyshevUpperBound(mo.z, max(mo.w - mo.z * mo.z, floors.y), e.y));
  return shadowReduceLightBleeding(p, shadowBleedReduction);
}
