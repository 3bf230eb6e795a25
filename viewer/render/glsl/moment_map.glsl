// VSM, EVSM, MSM and ESM read the blurred moments (lookup/moment_map.cpp) as sample_moments does,
// bilinear between four texels, each texel's box sum taken from the depth texture on the spot: the CPU's
// prefiltered texture, without a second render target.
uniform int shadowFilterKernelSize;  // the moment filters: the blur's side
// The filter's moment encoding (MomentEncoding::of_depth and stored), which the pass writes after
// the filters from their registrations (shadow_map_pass.cpp, filters_glsl): each filter's
// shadowMomentsOf_<name> and, where it keeps less than float32, shadowStoredMoments_<name>.
vec4 shadowMomentsOf(float depth);
vec4 shadowStoredMoments(vec4 blurred);
// blurred_moments at one texel: the N×N box (N/2 texels back, N − 1 − N/2 ahead, each axis clamped
// to the tile), what its two separable passes leave there, as the texel stores it.
vec4 shadowBlurredMoments(int i, ivec2 texel) {
  int side = shadowFilterKernelSize, before = side / 2, after = side - 1 - before;
  ivec2 first = ivec2(shadowMapTileTexels[i].xy), last = ivec2(shadowMapTileTexels[i].zw);
  vec4 sum = vec4(0.0);
  for (int dy = -before; dy <= after; ++dy)
    for (int dx = -before; dx <= after; ++dx)
      sum += shadowMomentsOf(shadowStoredDepth(clamp(texel + ivec2(dx, dy), first, last)));
  return shadowStoredMoments(sum / float(side * side));
}
// sample_moments: bilinear between the four nearest texel centres, kept in the tile.
vec4 shadowSampleMoments(int i, vec2 uv) {
  vec4 tile = shadowMapViewport[i];
  vec2 t = (tile.xy + uv * (tile.zw - tile.xy)) * float(shadowResolution) - 0.5;  // texel centres at whole numbers
  vec2 base = floor(t), f = t - base;
  ivec2 first = ivec2(shadowMapTileTexels[i].xy), last = ivec2(shadowMapTileTexels[i].zw), b = ivec2(base);
  vec4 m00 = shadowBlurredMoments(i, clamp(b, first, last));
  vec4 m10 = shadowBlurredMoments(i, clamp(b + ivec2(1, 0), first, last));
  vec4 m01 = shadowBlurredMoments(i, clamp(b + ivec2(0, 1), first, last));
  vec4 m11 = shadowBlurredMoments(i, clamp(b + ivec2(1, 1), first, last));
  return mix(mix(m00, m10, f.x), mix(m01, m11, f.x), f.y);
}
