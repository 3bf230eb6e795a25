#include "scene/image_size.hpp"

#include <algorithm>
#include <cmath>

namespace shadowlab {

glm::ivec2 image_size_within(const Camera& camera, int width, int height) {
    // As wide as allowed, unless the height at that width would not fit: then as tall as allowed.
    const int full_width_height = int(std::lround(width / camera.aspect));
    if (full_width_height <= height) return {std::max(1, width), std::max(1, full_width_height)};
    return {std::max(1, int(std::lround(height * camera.aspect))), std::max(1, height)};
}

}  // namespace shadowlab
