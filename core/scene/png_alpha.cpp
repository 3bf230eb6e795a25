#include "scene/png_alpha.hpp"

#include <cstring>
#include <memory>
#include <stdexcept>
#include <png.h>

namespace shadowlab {
namespace {

// Frees what libpng holds for an image whatever way the reading ends.
struct ImageReading {
    png_image image;
    ImageReading() {
        std::memset(&image, 0, sizeof image);
        image.version = PNG_IMAGE_VERSION;
    }
    ~ImageReading() { png_image_free(&image); }
    ImageReading(const ImageReading&) = delete;
    ImageReading& operator=(const ImageReading&) = delete;

    [[noreturn]] void refuse(const std::string& problem) const {
        throw std::invalid_argument(problem.empty() ? std::string(image.message) : problem);
    }
};

}  // namespace

AlphaTexture decode_png_alpha(const std::string& bytes, const std::string& file, AlphaChannel channel) {
    static constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    if (bytes.size() < sizeof kSignature || std::memcmp(bytes.data(), kSignature, sizeof kSignature) != 0)
        throw std::invalid_argument("not a PNG image (ShadowLab reads PNG textures)");
    ImageReading reading;
    if (!png_image_begin_read_from_memory(&reading.image, bytes.data(), bytes.size())) reading.refuse("");
    const png_uint_32 width = reading.image.width, height = reading.image.height;
    if (width == 0 || height == 0 || width > kMaxTextureSide || height > kMaxTextureSide)
        reading.refuse(std::to_string(width) + " x " + std::to_string(height) + " texels: a side beyond 1.." +
                       std::to_string(kMaxTextureSide));
    const bool grey = channel == AlphaChannel::alpha_else_grey && !(reading.image.format & PNG_FORMAT_FLAG_ALPHA);
    reading.image.format = PNG_FORMAT_RGBA;
    std::vector<png_byte> rgba(PNG_IMAGE_SIZE(reading.image));
    if (!png_image_finish_read(&reading.image, nullptr, rgba.data(), 0, nullptr)) reading.refuse("");
    AlphaTexture texture{.width = int(width), .height = int(height), .alpha = {}, .file = file};
    texture.alpha.resize(std::size_t{width} * height);
    // The file's first row is the image's top; a grey image's red is its grey (libpng expands it).
    for (png_uint_32 row = 0; row < height; ++row)
        for (png_uint_32 x = 0; x < width; ++x)
            texture.alpha[std::size_t{height - 1 - row} * width + x] =
                rgba[(std::size_t{row} * width + x) * 4 + (grey ? 0 : 3)] / 255.0f;
    return texture;
}

}  // namespace shadowlab
