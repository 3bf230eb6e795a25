// Stage 2, the depth biases (lookup/depth_bias.cpp) under map i: the texel's world size across the
// light, the slope-scaled bias and the receiver's plane, each a function of the CPU's name.
uniform float shadowBiasConstant;      // world units along the light
uniform float shadowBiasSlopeScale;    // times the slope-scaled bias
uniform float shadowBiasNormalOffset;  // texels
// across(): two unit directions perpendicular to l and to each other.
void shadowAcross(vec3 l, out vec3 a, out vec3 b) {
  a = normalize(cross(l, abs(l.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
  b = cross(l, a);
}
// smallest_singular_value (math/singular_values.hpp) of the 2x2 matrix (j0 j1), as σ_min² = 2 det² /
// (f + √(f² − 4 det²)): the same value without the float32 cancellation of (f − √(f² − 4 det²)) / 2
// where the map stretches one way far more than the other.
float shadowSmallestSingularValue(vec2 j0, vec2 j1) {
  float f = dot(j0, j0) + dot(j1, j1), det = j0.x * j1.y - j0.y * j1.x;
  float larger = f + sqrt(max(0.0, f * f - 4.0 * det * det));
  return larger > 0.0 ? sqrt(2.0 * det * det / larger) : 0.0;
}
// texel_world_size: 1 / (texels σ_min(J)), J = d(u, v) per world unit across the light. 0 where the
// CPU's is infinite (the map sees no area there): every use below then takes no offset, no
// slope-scaled bias and no radius, as the CPU's finite_or does.
float shadowTexelWorldSize(int i, float texels, vec3 l, vec3 p) {
  vec3 a, b;
  shadowAcross(l, a, b);
  float sigmaMin = shadowSmallestSingularValue(shadowUvDerivative(i, p, a), shadowUvDerivative(i, p, b));
  return sigmaMin > 0.0 ? 1.0 / (texels * sigmaMin) : 0.0;
}
// A world length across the light at a texel's world size, in the map's texels (0 for no size).
float shadowInTexels(float worldLength, float texelWorld) { return texelWorld > 0.0 ? worldLength / texelWorld : 0.0; }
// slope_scaled_bias: a texel's world width times 1 + tan θ (clamped to 10).
float shadowSlopeScaledBias(float texelWorld, float cosTheta) {
  float tanTheta = min(10.0, sqrt(max(0.0, 1.0 - cosTheta * cosTheta)) / max(cosTheta, 1e-6));
  return texelWorld * (1.0 + tanTheta);
}
// receiver_plane_gradient: ∂d/∂(u, v) on the plane through p with normal n, g = (∂d/∂s₁, ∂d/∂s₂) J⁻¹
// for two directions s₁, s₂ in the plane; 0 where the map sees the plane edge-on.
vec2 shadowReceiverPlaneGradient(int i, vec3 p, vec3 n) {
  vec3 s1, s2;
  shadowAcross(n, s1, s2);
  mat2 j = mat2(shadowUvDerivative(i, p, s1), shadowUvDerivative(i, p, s2));
  vec2 along = vec2(shadowDepthSlope(i, s1, p), shadowDepthSlope(i, s2, p));
  if (!(abs(determinant(j)) > 1e-12 * (dot(j[0], j[0]) + dot(j[1], j[1])))) return vec2(0.0);
  return along * inverse(j);  // a row vector times J⁻¹
}
