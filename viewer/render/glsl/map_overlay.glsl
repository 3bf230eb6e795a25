// Stage 2, the overlay (render/map_overlay.hpp): the selected map's palette colour (in a band both,
// crossfaded by the weight), or its texels per pixel on the ramp: the pixel's footprint in the map's
// texels as OpenGL sizes it to pick a mip level (the scale factor ρ, §8.14 of the 4.5 core profile):
// the longer of d(u, v)/dx and d(u, v)/dy across the screen, in the tile's texels.
uniform vec3 shadowPalette[shadowMaxMaps];
uniform vec3 shadowRamp[shadowMaxRampStops];
uniform int shadowRampCount;
vec3 shadowRampColour(float t) {
  float s = clamp(t, 0.0, 1.0) * float(shadowRampCount - 1);
  int k = min(int(s), shadowRampCount - 2);
  return mix(shadowRamp[k], shadowRamp[k + 1], s - float(k));
}
float shadowTexelsPerPixel(int i, vec3 p, vec3 dpdx, vec3 dpdy) {
  return shadowTileResolution(i) * max(length(shadowUvDerivative(i, p, dpdx)), length(shadowUvDerivative(i, p, dpdy)));
}
vec4 shadowOverlaid(vec4 colour, int i, float w, vec3 p, vec3 dpdx, vec3 dpdy) {
  if (shadowOverlay == shadowOverlayNone || i < 0) return colour;
  vec3 tint;
  if (shadowOverlay == shadowOverlayCascadeIndex)
    tint = w > 0.0 ? mix(shadowPalette[i], shadowPalette[i + 1], w) : shadowPalette[i];
  else  // texels_ramp_position
    tint = shadowRampColour((shadowTexelsLog2Range - log2(max(shadowTexelsPerPixel(i, p, dpdx, dpdy), 1e-6))) /
                            (2.0 * shadowTexelsLog2Range));
  return vec4(mix(colour.rgb, tint, shadowOverlayStrength), colour.a);
}
