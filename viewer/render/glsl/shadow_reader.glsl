// Stage 2, the lookup under one map: ShadowReader (lookup/shadow_reader.cpp) step by step, its
// functions under the same names: under and lit_share, which hard, pcf and pcss read through.
uniform int shadowLitThreshold;  // 1: the lit mask, the visibility thresholded at one half
// texel_centre_uv: the centre of a texture texel in map i's (u, v).
vec2 shadowTexelCentreUv(int i, ivec2 texel) {
  vec4 tile = shadowMapViewport[i];
  return ((vec2(texel) + 0.5) / float(shadowResolution) - tile.xy) / (tile.zw - tile.xy);
}
// biased_depth: the map's depth of p moved `bias` world units back toward the light; where that
// reaches the light or the map's centre, below every stored depth (lit by any texel).
float shadowBiasedDepth(int i, vec3 p, vec3 l, float bias) {
  vec4 h = shadowHomogeneous(i, p - bias * l);
  return h.w > 0.0 && shadowHemisphereSide(i, p - bias * l) >= 0.0 ? h.z / h.w : -shadowUnbounded;
}
// The receiver under one map (MapReceiver).
struct ShadowMapReceiver {
  vec3 position;        // the point looked up: the receiver, moved by the normal offset
  vec3 lightDirection;  // the way light travels there
  float texels;         // across the map's tile
  vec2 uv;
  float depth;          // the point's depth, less the bias in depth units
  vec2 planeGradient;   // receiver plane: ∂d/∂(u, v); 0 when off
  float texelWorld;     // a texel's world width across the light there (0: no size)
};
// under: the normal offset moves the point, then the constant and slope-scaled biases (world lengths)
// move it nearer the light along the light ray for its depth alone. False off the map.
bool shadowUnder(int i, vec3 position, vec3 normal, out ShadowMapReceiver m) {
  m.texels = shadowTileResolution(i);
  vec3 l = surfaceAlongLight(position);
  m.lightDirection = l;
  m.texelWorld = shadowTexelWorldSize(i, m.texels, l, position);
  vec3 p = position + normal * (shadowBiasNormalOffset * m.texelWorld);
  m.position = p;
  vec4 h = shadowHomogeneous(i, p);
  if (!shadowOnMap(h)) return false;
  m.uv = h.xy / h.w;
  float slopeScaled =
      shadowBiasSlopeScale > 0.0 ? shadowBiasSlopeScale * shadowSlopeScaledBias(m.texelWorld, dot(normal, -l)) : 0.0;
  m.depth = shadowBiasedDepth(i, p, l, shadowBiasConstant + slopeScaled);
  m.planeGradient = shadowBiasReceiverPlane == 1 ? shadowReceiverPlaneGradient(i, p, normal) : vec2(0.0);
  return true;
}
// lit_share: the weighted share of taps the receiver passes, each reading its nearest texel (kept in
// the tile) and comparing the receiver's depth there, on its plane when the receiver-plane bias is on.
float shadowLitShare(int i, ShadowMapReceiver m, float radiusTexels, float rotation) {
  float c = cos(rotation), s = sin(rotation);
  float lit = 0.0;
  for (int k = 0; k < shadowTapCount; ++k) {
    ivec2 texel = shadowTexelOf(i, m.uv + shadowRotated(shadowTaps[k].xy, c, s) * (radiusTexels / m.texels));
    float receiver = m.depth + dot(m.planeGradient, shadowTexelCentreUv(i, texel) - m.uv);
    if (receiver <= shadowStoredDepth(texel)) lit += shadowTaps[k].z;
  }
  return min(lit, 1.0);  // the weights' rounding
}
