#include "maps/clip_conventions.hpp"

#include "math/matrix.hpp"

namespace shadowlab {

glm::dmat4 uvz_from_clip(const ClipConventions& c) {
    // Each row is linear in (x, y, z, w), so the division by w still follows it: u w = (x + w) / 2.
    const double v_sign = c.v == TextureV::up ? 1.0 : -1.0;
    // The depth after the division, t in [0, 1] from the near plane to the far: (z / w + 1) / 2 or z / w.
    glm::dvec4 depth_row =
        c.depth == ClipDepth::minus_one_to_one ? glm::dvec4(0.0, 0.0, 0.5, 0.5) : glm::dvec4(0.0, 0.0, 1.0, 0.0);
    if (c.reversed_z) depth_row = glm::dvec4(0.0, 0.0, 0.0, 1.0) - depth_row;  // 1 - t: near at 1 turned to near at 0
    return from_rows({0.5, 0.0, 0.0, 0.5}, {0.0, 0.5 * v_sign, 0.0, 0.5}, depth_row, {0.0, 0.0, 0.0, 1.0});
}

}  // namespace shadowlab
