#pragma once
// The volume a projective matrix maps onto a box: a warp's frustum, a map's volume (its unit cube
// taken back to the world).
#include <array>
#include <glm/glm.hpp>

#include "geometry/aabb.hpp"
#include "geometry/frustum.hpp"

namespace shadowlab {

// The volume that `box_from_space` (projective) maps onto `box`, as a frustum: the box's corners
// taken back through its inverse. `depth_axis` is the box's axis that runs from the frustum's near
// face (box.min) to its far face (box.max): z for a map, y for LiSPSM's warp, which looks along y.
inline Frustum preimage_of_box(const glm::dmat4& box_from_space, const Aabb& box, int depth_axis = 2) {
    const glm::dmat4 space_from_box = glm::inverse(box_from_space);
    const int a = (depth_axis + 1) % 3, b = (depth_axis + 2) % 3;  // the image axes, in the frustum's (x, y) order
    const std::array<glm::dvec2, 4> image_corners{
        {{0, 0}, {1, 0}, {1, 1}, {0, 1}}};  // (-x,-y), (+x,-y), (+x,+y), (-x,+y)
    Frustum f;
    glm::dvec3 centre(0.0);
    for (int i = 0; i < 8; ++i) {
        glm::dvec3 p;
        p[depth_axis] = i < 4 ? box.min[depth_axis] : box.max[depth_axis];
        p[a] = image_corners[i % 4].x > 0 ? box.max[a] : box.min[a];
        p[b] = image_corners[i % 4].y > 0 ? box.max[b] : box.min[b];
        const glm::dvec4 h = space_from_box * glm::dvec4(p, 1.0);
        f.corners[i] = glm::dvec3(h) / h.w;
        centre += f.corners[i] / 8.0;
    }
    // Each face's plane by Newell's normal (any four corners, even slightly warped), turned outward.
    const std::array<std::array<int, 4>, 6> faces{
        {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 3, 7, 4}, {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 2, 6, 7}}};
    for (int k = 0; k < 6; ++k) {
        glm::dvec3 normal(0.0), mid(0.0);
        for (int j = 0; j < 4; ++j) {
            const glm::dvec3 &p = f.corners[faces[k][j]], &q = f.corners[faces[k][(j + 1) % 4]];
            normal += glm::cross(p, q);
            mid += p / 4.0;
        }
        if (glm::dot(normal, mid - centre) < 0.0) normal = -normal;
        f.planes[k] = Plane::through(mid, normal);
    }
    return f;
}

}  // namespace shadowlab
