#include "scene/png_alpha.hpp"

namespace shadowlab {

AlphaTexture decode_png_alpha(const std::string& bytes, const std::string& file, AlphaChannel channel) {
    const PngImage image = decode_png(bytes);
    const bool grey = channel == AlphaChannel::alpha_else_grey && !image.has_alpha;
    AlphaTexture texture{.width = image.width, .height = image.height, .alpha = {}, .file = file};
    texture.alpha.resize(std::size_t(image.width) * std::size_t(image.height));
    // The file's first row is the image's top; a grey image's red is its grey (libpng expands it).
    for (int row = 0; row < image.height; ++row)
        for (int x = 0; x < image.width; ++x)
            texture.alpha[std::size_t(image.height - 1 - row) * image.width + x] =
                image.rgba[(std::size_t(row) * image.width + x) * 4 + (grey ? 0 : 3)] / 255.0f;
    return texture;
}

}  // namespace shadowlab
