// Both stages: a paraboloid hemisphere (maps/paraboloid_projection.cpp) line by line.
uniform vec3 shadowMapParaboloidCentre[shadowMaxMaps];
uniform mat4 shadowMapParaboloidFrame[shadowMaxMaps];  // frame_from_world in the upper-left 3x3
uniform float shadowMapParaboloidNear[shadowMaxMaps];
uniform float shadowMapParaboloidFar[shadowMaxMaps];
vec3 shadowInParaboloidFrame(int i, vec3 p) {
  return mat3(shadowMapParaboloidFrame[i]) * (p - shadowMapParaboloidCentre[i]);
}
vec4 shadowParaboloidHomogeneous(int i, vec3 p) {
  vec3 q = shadowInParaboloidFrame(i, p);
  float dist = length(q);
  if (!(dist > 0.0)) return vec4(0.0);
  vec3 d = q / dist;
  float denominator = 1.0 + d.z;
  if (!(denominator > 1e-12)) return vec4(0.0);  // straight behind: the map's singular point
  vec2 uv = (d.xy / denominator + 1.0) / 2.0;
  float nearD = shadowMapParaboloidNear[i], farD = shadowMapParaboloidFar[i];
  return vec4(uv, (dist - nearD) / (farD - nearD), 1.0);
}
// The signed distance to the hemisphere's plane (>= 0: its side).
float shadowParaboloidClipDistance(int i, vec3 p) { return shadowInParaboloidFrame(i, p).z; }
vec2 shadowParaboloidUv(int i, vec3 p) {
  vec4 h = shadowParaboloidHomogeneous(i, p);
  return h.xy / h.w;
}
// A central difference sized by the distance to the centre.
vec2 shadowParaboloidUvDerivative(int i, vec3 p, vec3 direction) {
  float step = 1e-3 * length(p - shadowMapParaboloidCentre[i]);  // float32: a coarser step than the CPU's
  return (shadowParaboloidUv(i, p + step * direction) - shadowParaboloidUv(i, p - step * direction)) / (2.0 * step);
}
// d = (|q| - near) / (far - near)
float shadowParaboloidDepthSlope(int i, vec3 l, vec3 p) {
  return dot(normalize(shadowInParaboloidFrame(i, p)), mat3(shadowMapParaboloidFrame[i]) * l) /
         (shadowMapParaboloidFar[i] - shadowMapParaboloidNear[i]);
}
// Back along a radial ray, d falls by 1 / (far - near) per unit.
float shadowParaboloidDistanceBackToDepth(int i, vec3 l, vec3 p, float depth) {
  vec4 h = shadowParaboloidHomogeneous(i, p);
  return (h.z - depth) * (shadowMapParaboloidFar[i] - shadowMapParaboloidNear[i]);
}
