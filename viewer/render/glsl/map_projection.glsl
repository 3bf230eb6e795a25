// Both stages: each map's point before the division, map_homogeneous and hemisphere_side
// (maps/map_lookup.cpp) line by line. A cube face is a linear map like any other.
uniform int shadowMapProjection[shadowMaxMaps];
uniform mat4 shadowMapWorldToUvz[shadowMaxMaps];
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
vec4 shadowHomogeneous(int i, vec3 p) {
  if (shadowMapProjection[i] == shadowParaboloid) return shadowParaboloidHomogeneous(i, p);
  return shadowMapWorldToUvz[i] * vec4(p, 1.0);
}
float shadowHemisphereSide(int i, vec3 p) {
  return shadowMapProjection[i] == shadowParaboloid ? shadowInParaboloidFrame(i, p).z : 1.0;
}
