// A textured material's colour (scene/base_colour.hpp): glTF's base colour, the linear factor times the
// texel (an sRGB texture: OpenGL decodes it to linear on reading), sRGB-encoded as BaseColour's
// shown_factor encodes an untextured one (IEC 61966-2-1), so that the shading takes it as it takes the
// palette's display colours.
uniform sampler2D surfaceBaseColour;
uniform vec3 surfaceBaseColourFactor;
vec3 surfaceSrgbFromLinear(vec3 linear) {
  return mix(12.92 * linear, 1.055 * pow(linear, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), linear));
}
vec3 surfaceBaseColourShown() {
  vec3 linear = clamp(surfaceBaseColourFactor * texture(surfaceBaseColour, shadowCasterUvVSOutput).rgb, 0.0, 1.0);
  return surfaceSrgbFromLinear(linear);
}
