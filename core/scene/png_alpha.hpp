#pragma once
// The alpha channel of a PNG image (scene/png_image). An image without an alpha channel reads as
// opaque (1).
#include <string>

#include "scene/alpha_test.hpp"
#include "scene/png_image.hpp"

namespace shadowlab {

// Which channel gives the coverage: the alpha channel (glTF's base colour alpha; opaque without one), or
// the alpha channel where the image has one and else its grey (OBJ's map_d, a scalar texture).
enum class AlphaChannel { alpha, alpha_else_grey };

// The image in `bytes`, rows turned so that row 0 is its bottom one (AlphaTexture); `file` names it in
// messages. Throws std::invalid_argument with the problem as decode_png does.
AlphaTexture decode_png_alpha(const std::string& bytes, const std::string& file,
                              AlphaChannel channel = AlphaChannel::alpha);

}  // namespace shadowlab
