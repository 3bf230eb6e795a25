#pragma once
// A PNG image as 8-bit RGBA (libpng's simplified API, which reports a bad file by its return value: no
// longjmp through our frames), the one decoder of the textures a model names: their alpha for the alpha
// tests (png_alpha), their colour for the Camera view (base_colour).
#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab {

// The larger side a texture may have: 16384² RGBA bytes are 1 GiB.
inline constexpr int kMaxTextureSide = 16384;

struct PngImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // row-major, the file's first row (the image's top) first
    bool has_alpha = false;          // the file has an alpha channel (without one, alpha reads 255)
};

// The image in `bytes`. Throws std::invalid_argument with the problem ("not a PNG image", "16385 x 2
// texels: a side beyond 1..16384", libpng's reason) on anything else.
PngImage decode_png(const std::string& bytes);

}  // namespace shadowlab
