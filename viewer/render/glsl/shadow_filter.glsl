// Stage 2, the filters (lookup/shadow_filter.hpp) as ShadowReader applies them: pcf's radius,
// chebyshev_visibility and map_visibility.
uniform float shadowFilterRadiusTexels;
uniform float shadowFilterRadiusWorld;   // > 0: overrides the radius in texels
// chebyshev_visibility: Chebyshev's bound at the receiver's depth; EVSM's variance floors scaled by
// each warp's slope, (c e^{cd})², so that they are the same in depth units.
float shadowChebyshevVisibility(int i, ShadowMapReceiver m) {
  vec4 mo = shadowSampleMoments(i, m.uv);
  float p;
  if (shadowFilterKind == shadowFilterVsm) {
    p = shadowChebyshevUpperBound(mo.x, max(mo.y - mo.x * mo.x, shadowMinVariance), m.depth);
  } else {
    vec2 e = shadowEvsmWarps(m.depth);
    vec2 slopes = vec2(shadowEvsmPositive, shadowEvsmNegative) * e;
    vec2 floors = shadowMinVariance * slopes * slopes;
    p = min(shadowChebyshevUpperBound(mo.x, max(mo.y - mo.x * mo.x, floors.x), e.x),
            shadowChebyshevUpperBound(mo.z, max(mo.w - mo.z * mo.z, floors.y), e.y));
  }
  return shadowReduceLightBleeding(p, shadowBleedReduction);
}
// map_visibility: one map's share of the light at the receiver; off the map, lit. Hard reads its one
// tap at the centre, which no radius moves.
float shadowMapVisibility(int i, vec3 position, vec3 normal, float rotation) {
  ShadowMapReceiver m;
  if (!shadowUnder(i, position, normal, m)) return 1.0;
  if (shadowFilterKind == shadowFilterPcss) return shadowSoftShadow(i, m, rotation);
  if (shadowFilterKind == shadowFilterVsm || shadowFilterKind == shadowFilterEvsm)
    return shadowChebyshevVisibility(i, m);
  float radius = shadowFilterRadiusWorld > 0.0 ? shadowInTexels(shadowFilterRadiusWorld, m.texelWorld)
                                               : shadowFilterRadiusTexels;
  return shadowLitShare(i, m, radius, shadowTapsTurn == 1 ? rotation : 0.0);
}
