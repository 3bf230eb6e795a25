// libFuzzer target: the input as a texture an alpha-tested material names (a glTF base colour texture,
// an OBJ map_d), through decode_png_alpha both ways: a refusal (std::invalid_argument) is the right
// answer to bad input; an accepted image has as many alpha values as texels, each in [0, 1].
#include <cstdint>
#include <stdexcept>
#include <string>

#include "every_method.hpp"
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
    return 0;
}
