#pragma once
// The viewer's pinhole camera (right-handed; it looks down -z of its view space).
#include <glm/glm.hpp>

#include "geometry/frustum.hpp"

namespace shadowlab {

struct Camera {
    glm::dvec3 position{0.0, 2.0, 10.0};
    glm::dvec3 target{0.0, 0.0, 0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fov_y_deg = 60.0;
    double aspect = 16.0 / 9.0;
    double near = 0.1;
    double far = 100.0;

    glm::dvec3 view_direction() const { return glm::normalize(target - position); }
    glm::dmat4 view_matrix() const;        // world -> view
    glm::dmat4 projection_matrix() const;  // view -> OpenGL clip space
    // The same with the far plane at infinity (Everitt and Kilgard 2002): points at infinity
    // (w = 0) in front of the eye land at depth 1 instead of being clipped.
    glm::dmat4 infinite_projection_matrix() const;
    Frustum frustum() const;               // in world space
};

}  // namespace shadowlab
