#pragma once
// The alpha channel of a PNG image (libpng's simplified API, which reports a bad file by its return
// value: no longjmp through our frames). An image without an alpha channel reads as opaque (1).
#include <string>

#include "scene/alpha_test.hpp"

namespace shadowlab {

// The larger side a texture may have: 16384² RGBA bytes are 1 GiB.
inline constexpr int kMaxTextureSide = 16384;

// Which channel gives the coverage: the alpha channel (glTF's base colour alpha; opaque without one), or
// the alpha channel where the image has one and else its grey (OBJ's map_d, a scalar texture).
enum class AlphaChannel { alpha, alpha_else_grey };

// The image in `bytes`, rows turned so that row 0 is its bottom one (AlphaTexture); `file` names it in
// messages. Throws std::invalid_argument with the problem ("not a PNG image", "16385 x 2 texels: a
// side beyond 16384", libpng's reason) on anything else.
AlphaTexture decode_png_alpha(const std::string& bytes, const std::string& file,
                              AlphaChannel channel = AlphaChannel::alpha);

}  // namespace shadowlab
