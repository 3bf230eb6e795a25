// Stage 2, after the projections: select_map, blend_of and texel_of (maps/map_lookup.cpp) line by
// line; uv_derivative, depth_slope and distance_back_to_depth are the kinds' (map_projection.glsl).
uniform int shadowMapCount;
uniform vec3 shadowMapFaceAxis[shadowMaxMaps];  // the face_axis rule's, each map's
uniform vec4 shadowMapViewport[shadowMaxMaps];    // (u0, v0, u1, v1): the tile in the texture
uniform vec4 shadowMapTileTexels[shadowMaxMaps];  // first and last texel (x, y, x, y) of the tile
uniform int shadowSelectionRule;
uniform vec3 shadowSelectionEye;
uniform vec3 shadowSelectionViewAxis;
uniform float shadowSelectionSplitDepths[shadowMaxMaps + 1];
uniform int shadowSelectionSplitCount;
uniform float shadowSelectionBlendBand;
uniform vec3 shadowSelectionCentre;
uniform sampler2D shadowDepth;
uniform int shadowResolution;
uniform int shadowDepthReversed;  // 1: the texture holds s = 1 − d (a reversed depth format)
// DepthMap::at: a texel's depth d, the format's stored value read back (the texture's own encoding
// already turned into [0, 1]).
float shadowStoredDepth(ivec2 texel) {
  float s = texelFetch(shadowDepth, texel, 0).r;
  return shadowDepthReversed == 1 ? 1.0 - s : s;
}
bool shadowInUnitRange(float t) { return t >= 0.0 && t <= 1.0; }  // false for NaN
bool shadowOnMap(vec4 h) { return h.w > 0.0 && shadowInUnitRange(h.x / h.w) && shadowInUnitRange(h.y / h.w); }
// The map whose face axis has the largest dot with r, the first on ties (nearest_face).
int shadowNearestFace(vec3 r) {
  int best = 0;
  for (int i = 1; i < shadowMapCount; ++i)
    if (dot(shadowMapFaceAxis[i], r) > dot(shadowMapFaceAxis[best], r)) best = i;
  return best;
}
float shadowViewDepth(vec3 p) { return dot(p - shadowSelectionEye, shadowSelectionViewAxis); }
// Map i serves view depths in [split i, split i + 1), the last split included.
int shadowByViewDepth(vec3 p) {
  float depth = shadowViewDepth(p);
  for (int i = 0; i + 1 < shadowSelectionSplitCount; ++i)
    if (depth >= shadowSelectionSplitDepths[i] &&
        (depth < shadowSelectionSplitDepths[i + 1] ||
         (i + 2 == shadowSelectionSplitCount && depth == shadowSelectionSplitDepths[i + 1])))
      return i;
  return -1;
}
// Whether map i holds p under the rules that take the first map holding it.
bool shadowHolds(int i, vec3 p) {
  if (shadowSelectionRule == shadowRuleTileBounds) return shadowOnMap(shadowHomogeneous(i, p));
  return shadowSelectionRule == shadowRuleHemisphere && shadowHemisphereSide(i, p) >= 0.0;
}
int shadowSelectMap(vec3 p) {
  if (shadowMapCount == 0) return -1;
  if (shadowSelectionRule == shadowRuleOnly) return 0;
  if (shadowSelectionRule == shadowRuleViewDepth) return shadowByViewDepth(p);
  if (shadowSelectionRule == shadowRuleFaceAxis) return shadowNearestFace(p - shadowSelectionCentre);
  for (int i = 0; i < shadowMapCount; ++i)
    if (shadowHolds(i, p)) return i;
  return -1;
}
// blend_of: map i + 1's share at p, rising from 0 to 1 over the last blend band of split i; none
// after the last split or under the other rules.
float shadowBlendWeight(int i, vec3 p) {
  if (shadowSelectionRule != shadowRuleViewDepth || !(shadowSelectionBlendBand > 0.0) ||
      !(i >= 0 && i + 2 < shadowSelectionSplitCount))
    return 0.0;
  float splitEnd = shadowSelectionSplitDepths[i + 1];
  float band = shadowSelectionBlendBand * (splitEnd - shadowSelectionSplitDepths[i]);
  return clamp((shadowViewDepth(p) - (splitEnd - band)) / band, 0.0, 1.0);
}
// The texel map i's (u, v) reads: the nearest, kept in the map's tile.
ivec2 shadowTexelOf(int i, vec2 uv) {
  vec4 tile = shadowMapViewport[i];
  vec2 t = (tile.xy + uv * (tile.zw - tile.xy)) * float(shadowResolution);
  return ivec2(clamp(floor(t), shadowMapTileTexels[i].xy, shadowMapTileTexels[i].zw));
}
float shadowTileResolution(int i) {
  return (shadowMapViewport[i].z - shadowMapViewport[i].x) * float(shadowResolution);
}
