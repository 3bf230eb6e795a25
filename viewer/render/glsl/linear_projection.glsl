// Both stages: a linear map or a cube face (maps/linear_projection.cpp) line by line; no clip plane.
uniform mat4 shadowMapWorldToUvz[shadowMaxMaps];
vec4 shadowLinearHomogeneous(int i, vec3 p) { return shadowMapWorldToUvz[i] * vec4(p, 1.0); }
// The quotient rule on the map's rows.
vec2 shadowLinearUvDerivative(int i, vec3 p, vec3 direction) {
  vec4 h = shadowMapWorldToUvz[i] * vec4(p, 1.0), dh = shadowMapWorldToUvz[i] * vec4(direction, 0.0);
  return (dh.xy * h.w - h.xy * dh.w) / (h.w * h.w);
}
float shadowLinearDepthSlope(int i, vec3 l, vec3 p) {
  vec4 h = shadowMapWorldToUvz[i] * vec4(p, 1.0), dh = shadowMapWorldToUvz[i] * vec4(l, 0.0);
  return (dh.z * h.w - h.z * dh.w) / (h.w * h.w);  // the quotient rule on d_pre / w
}
// At p - s l the map holds (h.z - s dh.z) / (h.w - s dh.w); set it to `depth` and solve for s.
float shadowLinearDistanceBackToDepth(int i, vec3 l, vec3 p, float depth) {
  vec4 h = shadowMapWorldToUvz[i] * vec4(p, 1.0), dh = shadowMapWorldToUvz[i] * vec4(l, 0.0);
  float s = (h.z - depth * h.w) / (dh.z - depth * dh.w);
  return !isinf(s) && !isnan(s) && s >= 0.0 ? s : shadowUnbounded;
}
