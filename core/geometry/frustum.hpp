#pragma once
// A view frustum as 8 world-space corners and 6 outward planes.
#include <array>
#include <glm/glm.hpp>

#include "geometry/plane.hpp"

namespace shadowlab {

struct Frustum {
    // Corners 0-3 on the near plane, 4-7 on the far plane, each as
    // (-x,-y), (+x,-y), (+x,+y), (-x,+y) in the camera's image axes.
    std::array<glm::dvec3, 8> corners;
    // Outward planes: near, far, left, right, bottom, top.
    std::array<Plane, 6> planes;

    bool contains(const glm::dvec3& p, double tolerance = 0.0) const {
        for (const Plane& plane : planes)
            if (plane.signed_distance(p) > tolerance) return false;
        return true;
    }
};

}  // namespace shadowlab
