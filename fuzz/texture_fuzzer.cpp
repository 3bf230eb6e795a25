// libFuzzer target: the input as a texture a material names (a glTF base colour texture, an OBJ map_d or
// map_Kd), through decode_png_alpha both ways and decode_colour_texture: a refusal
// (std::invalid_argument) is the right answer to bad input; an accepted image has as many alpha values
// as texels, each in [0, 1], or four colour bytes a texel.
#include <cstdint>
#include <stdexcept>
#include <string>

#include "every_method.hpp"
#include "scene/base_colour.hpp"
#include "scene/png_alpha.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace shadowlab;
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    for (const AlphaChannel channel : {AlphaChannel::alpha, AlphaChannel::alpha_else_grey}) {
        try {
            const AlphaTexture texture = decode_png_alpha(bytes, "fuzzed.png", channel);
            if (texture.alpha.size() != std::size_t(texture.width) * std::size_t(texture.height))
                fuzzing::bug("an accepted texture", "its alpha values are not one per texel");
            for (const float alpha : texture.alpha)
                if (!(alpha >= 0.0f && alpha <= 1.0f)) fuzzing::bug("an accepted texture", "an alpha beyond [0, 1]");
        } catch (const std::invalid_argument&) {
        }
    }
    try {
        const ColourTexture texture = decode_colour_texture(bytes, "fuzzed.png");
        if (texture.srgb_rgba.size() != 4 * std::size_t(texture.width) * std::size_t(texture.height))
            fuzzing::bug("an accepted colour texture", "its bytes are not four per texel");
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
