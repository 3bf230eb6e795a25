// Both stages: a logarithmic perspective map (maps/log_perspective_projection.cpp) line by line: the
// perspective 4x4 (shadowMapWorldToUvz, linear_projection.glsl) for u and depth, v the log of its w.
uniform float shadowMapLogNear[shadowMaxMaps];
uniform float shadowMapLogFar[shadowMaxMaps];
float shadowLogClipW(int i) { return 0.5 * shadowMapLogNear[i]; }  // kLogClipShare of near
float shadowLogRange(int i) { return log(shadowMapLogFar[i] / shadowMapLogNear[i]); }
// v = log(w / near) / log(far / near), w at or below the clip plane read as on it.
float shadowLogWarpV(int i, float w) {
  return log(max(w, shadowLogClipW(i)) / shadowMapLogNear[i]) / shadowLogRange(i);
}
vec4 shadowLogPerspectiveHomogeneous(int i, vec3 p) {
  vec4 h = shadowMapWorldToUvz[i] * vec4(p, 1.0);
  return vec4(h.x, shadowLogWarpV(i, h.w) * h.w, h.z, h.w);
}
// The signed distance to the plane w = near / 2 (>= 0: drawn).
float shadowLogPerspectiveClipDistance(int i, vec3 p) {
  return (shadowMapWorldToUvz[i] * vec4(p, 1.0)).w - shadowLogClipW(i);
}
// u by the quotient rule on the rows; v changes by (dw / w) / log(far / near).
vec2 shadowLogPerspectiveUvDerivative(int i, vec3 p, vec3 direction) {
  vec4 h = shadowMapWorldToUvz[i] * vec4(p, 1.0), dh = shadowMapWorldToUvz[i] * vec4(direction, 0.0);
  return vec2((dh.x * h.w - h.x * dh.w) / (h.w * h.w), dh.w / (h.w * shadowLogRange(i)));
}
// Depth is the perspective's.
float shadowLogPerspectiveDepthSlope(int i, vec3 l, vec3 p) { return shadowLinearDepthSlope(i, l, p); }
float shadowLogPerspectiveDistanceBackToDepth(int i, vec3 l, vec3 p, float depth) {
  return shadowLinearDistanceBackToDepth(i, l, p, depth);
}
