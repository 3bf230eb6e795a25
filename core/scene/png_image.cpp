#include "scene/png_image.hpp"

#include <cstring>
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

PngImage decode_png(const std::string& bytes) {
    static constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    if (bytes.size() < sizeof kSignature || std::memcmp(bytes.data(), kSignature, sizeof kSignature) != 0)
        throw std::invalid_argument("not a PNG image (ShadowLab reads PNG textures)");
    ImageReading reading;
    if (!png_image_begin_read_from_memory(&reading.image, bytes.data(), bytes.size())) reading.refuse("");
    const png_uint_32 width = reading.image.width, height = reading.image.height;
    if (width == 0 || height == 0 || width > kMaxTextureSide || height > kMaxTextureSide)
        reading.refuse(std::to_string(width) + " x " + std::to_string(height) + " texels: a side beyond 1.." +
                       std::to_string(kMaxTextureSide));
    PngImage image{.width = int(width),
                   .height = int(height),
                   .rgba = {},
                   .has_alpha = (reading.image.format & PNG_FORMAT_FLAG_ALPHA) != 0};
    reading.image.format = PNG_FORMAT_RGBA;  // a grey image's grey in red, green and blue
    image.rgba.resize(PNG_IMAGE_SIZE(reading.image));
    if (!png_image_finish_read(&reading.image, nullptr, image.rgba.data(), 0, nullptr)) reading.refuse("");
    return image;
}

}  // namespace shadowlab
