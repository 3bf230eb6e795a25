#include "scene/base_colour.hpp"

#include <cmath>
#include <cstring>

#include "scene/png_image.hpp"

namespace shadowlab {

// IEC 61966-2-1 (1999), section 5.2: a linear segment below the knee, a 2.4 power above it.
double linear_from_srgb(double encoded) {
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

double srgb_from_linear(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

glm::dvec3 shown_factor(const BaseColour& colour) {
    const glm::dvec3 linear = glm::clamp(colour.factor, 0.0, 1.0);
    return {srgb_from_linear(linear.r), srgb_from_linear(linear.g), srgb_from_linear(linear.b)};
}

ColourTexture decode_colour_texture(const std::string& bytes, const std::string& file) {
    const PngImage image = decode_png(bytes);
    ColourTexture texture{.width = image.width, .height = image.height, .srgb_rgba = {}, .file = file};
    texture.srgb_rgba.resize(image.rgba.size());
    const std::size_t row_bytes = std::size_t(image.width) * 4;
    for (int row = 0; row < image.height; ++row)  // the file's first row is the image's top
        std::memcpy(texture.srgb_rgba.data() + std::size_t(image.height - 1 - row) * row_bytes,
                    image.rgba.data() + std::size_t(row) * row_bytes, row_bytes);
    return texture;
}

}  // namespace shadowlab
