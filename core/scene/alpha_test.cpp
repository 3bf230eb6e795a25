#include "scene/alpha_test.hpp"

#include <cmath>

namespace shadowlab {
namespace {

// The texel holding coordinate t of a side of `size` texels, wrapped (GL_REPEAT, GL_NEAREST).
int wrapped_texel(double t, int size) {
    const double wrapped = t - std::floor(t);  // [0, 1], 1 only by rounding
    return std::min(static_cast<int>(wrapped * size), size - 1);
}

}  // namespace

float AlphaTexture::at(const glm::dvec2& uv) const {
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return 1.0f;
    const int x = wrapped_texel(uv.x, width), y = wrapped_texel(uv.y, height);
    return alpha[static_cast<std::size_t>(y) * width + x];
}

}  // namespace shadowlab
