// The shading of render/surface_shading.hpp; the seen normal from derivatives, as VTK takes it for
// meshes without normals (ours), so that faces stay flat and the shadow test and the shading agree.
uniform vec4 surfaceLight;  // (direction it travels, 0) for a directional light, (position, 1) otherwise
uniform vec3 surfaceEye;
uniform int surfaceLitMask;
in vec4 surfaceWorldVSOutput;
vec3 surfaceSeenNormal(vec3 p) {
  vec3 n = normalize(cross(dFdx(p), dFdy(p)));
  return dot(n, surfaceEye - p) < 0.0 ? -n : n;
}
vec3 surfaceAlongLight(vec3 p) { return surfaceLight.w == 0.0 ? normalize(surfaceLight.xyz) : normalize(p - surfaceLight.xyz); }
vec4 surfaceColour(vec3 ambient, vec3 diffuse, float opacity, vec3 p, vec3 n, float lit) {
  if (surfaceLitMask == 1) return vec4(vec3(lit), 1.0);
  float cosine = dot(n, -surfaceAlongLight(p));
  float shadowed = (1.0 - lit) * smoothstep(0.0, 0.1, cosine);
  return vec4((ambient + diffuse * max(cosine, 0.0)) * mix(vec3(1.0), shadowTint, shadowed), opacity);
}
