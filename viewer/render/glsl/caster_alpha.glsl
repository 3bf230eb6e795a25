// Stage 1's alpha test (scene/alpha_test.hpp, AlphaTest::keeps): a caster's fragment is there where
// its texture's alpha (the nearest texel, repeated) times the factor is at least the cutoff, and is
// discarded elsewhere, as the CPU rasterizer leaves such a texel as it was. The texture coordinates
// arrive interpolated perspective-correct in the map's homogeneous space, as the CPU's are
// (shadowCasterUvVSOutput: pass_texture_coordinates, render/stage_one_casters.hpp).
uniform sampler2D shadowCasterAlpha;
uniform float shadowCasterAlphaFactor;
uniform float shadowCasterAlphaCutoff;

bool shadowCasterKept() {
  return shadowCasterAlphaFactor * texture(shadowCasterAlpha, shadowCasterUvVSOutput).r >= shadowCasterAlphaCutoff;
}
