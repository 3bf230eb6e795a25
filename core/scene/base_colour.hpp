#pragma once
// A material's base colour (glTF 2.0 pbrMetallicRoughness.baseColorFactor and .baseColorTexture; OBJ's Kd
// and map_Kd): the colour the Camera view shades its surfaces with in place of the object's palette
// colour. glTF 2.0 (section 3.9.2) gives the factor as linear values and the texture sRGB-encoded, the
// base colour being their product once the texel is decoded: factor × linear(texel). The views' own
// colours are display values (the palette, shaded with no framebuffer encoding), so a material is shown
// as a glTF viewer shows it under a full white light, its linear base colour sRGB-encoded, and then shaded
// as a palette colour is (render/surface_shading.hpp). OBJ's Kd is read as glTF's factor, map_Kd as its
// texture.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>
#include <glm/glm.hpp>

namespace shadowlab {

// A PNG image's colour as its file stores it (sRGB-encoded bytes, RGBA), row 0 its bottom row: texture
// coordinates as Assimp gives them (v up), as AlphaTexture keeps its alpha.
struct ColourTexture {
    int width = 0, height = 0;
    std::vector<std::uint8_t> srgb_rgba;  // row-major, 4 bytes a texel, y * width + x, y from the bottom
    std::string file;                     // where it was read from, for messages
};

struct BaseColour {
    glm::dvec3 factor{1.0};                        // linear, each in [0, 1]
    std::shared_ptr<const ColourTexture> texture;  // null: the factor alone
};

// One triangle's base colour and its corners' texture coordinates (TEXCOORD_0, v up).
struct TriangleColour {
    std::shared_ptr<const BaseColour> colour;  // null: its object's palette colour
    std::array<glm::dvec2, 3> uv{};
};

// IEC 61966-2-1's transfer functions (glTF's, and OpenGL's for an sRGB texture): an encoded value in
// [0, 1] to its linear value and back.
double linear_from_srgb(double encoded);
double srgb_from_linear(double linear);

// The factor as the views show an untextured material: sRGB-encoded, each channel in [0, 1].
glm::dvec3 shown_factor(const BaseColour& colour);

// The PNG image in `bytes` (scene/png_image), rows turned so that row 0 is its bottom one; `file` names
// it in messages. Throws std::invalid_argument with the problem as decode_png does.
ColourTexture decode_colour_texture(const std::string& bytes, const std::string& file);

}  // namespace shadowlab
