// Percentage-closer soft shadows (lookup/pcss_filter.cpp): the light's size, penumbra_width
// (lookup/pcss.cpp) and soft_shadow, over the Poisson disk turned per pixel.
uniform int shadowLightDirectional;
uniform vec3 shadowLightPosition;
uniform float shadowLightRadius;
uniform float shadowLightTanAngularRadius;
// penumbra_width (lookup/pcss.cpp) at receiver point p for a blocker delta before it: 2 Δ tan α for
// the sun, (L − (L − Δ)) 2R / (L − Δ) for a sphere light; a blocker at the light: unbounded.
float shadowPenumbraWidth(vec3 p, float delta) {
  if (shadowLightDirectional == 1) return 2.0 * delta * shadowLightTanAngularRadius;
  float receiverDistance = distance(p, shadowLightPosition);
  float blockerDistance = receiverDistance - delta;
  if (!(blockerDistance > 0.0)) return shadowUnbounded;
  return (receiverDistance - blockerDistance) * 2.0 * shadowLightRadius / blockerDistance;
}
// soft_shadow: PCSS's three steps over the Poisson disk.
float shadowSoftShadow(int i, ShadowMapReceiver m, float rotation) {
  // Step 1, the blocker search over the light's footprint back to the map's near plane (d = 0), at
  // most kMaxSearchTexels (blocker_search_radius: half the penumbra).
  float toNearPlane = shadowDistanceBackToDepth(i, m.lightDirection, m.position, 0.0);
  float search =
      min(shadowInTexels(shadowPenumbraWidth(m.position, toNearPlane) / 2.0, m.texelWorld), shadowMaxSearchTexels);
  float c = cos(rotation), s = sin(rotation);
  float blockerDepth = 0.0;
  int blockers = 0;
  for (int k = 0; k < shadowTapCount; ++k) {
    ivec2 texel = shadowTexelOf(i, m.uv + shadowRotated(shadowTaps[k].xy, c, s) * (search / m.texels));
    float stored = shadowStoredDepth(texel);
    if (stored < m.depth) {
      blockerDepth += stored;
      ++blockers;
    }
  }
  if (blockers == 0) return 1.0;  // nothing between the receiver and the light
  blockerDepth /= float(blockers);
  // Step 2, the penumbra the average blocker casts; step 3, PCF over it (never wider than the search).
  float blockerDistance = shadowDistanceBackToDepth(i, m.lightDirection, m.position, blockerDepth);
  float radius = shadowInTexels(shadowPenumbraWidth(m.position, blockerDistance) / 2.0, m.texelWorld);
  return shadowLitShare(i, m, min(radius, search), rotation);
}
float shadowFilter_pcss(int i, ShadowMapReceiver m, float rotation) { return shadowSoftShadow(i, m, rotation); }
