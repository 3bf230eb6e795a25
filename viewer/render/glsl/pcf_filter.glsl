// Percentage-closer filtering (lookup/pcf_filter.cpp): the kernel's taps over its radius in texels,
// or its world radius across the light; the Poisson disk turned per pixel.
uniform float shadowFilterRadiusTexels;
uniform float shadowFilterRadiusWorld;  // > 0: overrides the radius in texels
float shadowFilter_pcf(int i, ShadowMapReceiver m, float rotation) {
  float radius = shadowFilterRadiusWorld > 0.0 ? shadowInTexels(shadowFilterRadiusWorld, m.texelWorld)
                                               : shadowFilterRadiusTexels;
  return shadowLitShare(i, m, radius, shadowTapsTurn == 1 ? rotation : 0.0);
}
