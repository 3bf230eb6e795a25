// Exponential variance shadow maps (lookup/variance_filters.cpp): the tighter of Chebyshev's bounds
// on the two warps' moments, the variance floors scaled by each warp's slope, (c e^{cd})², so that
// they are the same in depth units.
float shadowFilter_evsm(int i, ShadowMapReceiver m, float rotation) {
  vec4 mo = shadowSampleMoments(i, m.uv, true);
  vec2 e = shadowEvsmWarps(m.depth);
  vec2 slopes = vec2(shadowEvsmPositive, shadowEvsmNegative) * e;
  vec2 floors = shadowMinVariance * slopes * slopes;
  float p = min(shadowChebyshevUpperBound(mo.x, max(mo.y - mo.x * mo.x, floors.x), e.x),
                shadowChebyshevUpperBound(mo.z, max(mo.w - mo.z * mo.z, floors.y), e.y));
  return shadowReduceLightBleeding(p, shadowBleedReduction);
}
