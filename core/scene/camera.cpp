#include "scene/camera.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "math/normalize.hpp"

namespace shadowlab {

// `up` as given (a scene built in code need not normalise it): lookAt would square it.
glm::dmat4 Camera::view_matrix() const { return glm::lookAt(position, target, normalize_safely(up)); }

glm::dmat4 Camera::projection_matrix() const {
    return glm::perspective(glm::radians(fov_y_deg), aspect, near, far);
}

glm::dmat4 Camera::infinite_projection_matrix() const {
    return glm::infinitePerspective(glm::radians(fov_y_deg), aspect, near);
}

// Built from the camera's axes rather than by inverting view-projection, which loses all
// precision when far / near is large.
Frustum Camera::frustum() const {
    const glm::dvec3 forward = view_direction();
    const glm::dvec3 right = normalize_safely(glm::cross(forward, up));
    const glm::dvec3 image_up = glm::cross(right, forward);
    const double tan_y = std::tan(glm::radians(fov_y_deg) / 2.0);
    const double tan_x = tan_y * aspect;

    Frustum f;
    const double distances[2] = {near, far};
    for (int i = 0; i < 2; ++i) {
        const glm::dvec3 center = position + forward * distances[i];
        const glm::dvec3 dx = right * (tan_x * distances[i]);
        const glm::dvec3 dy = image_up * (tan_y * distances[i]);
        f.corners[4 * i + 0] = center - dx - dy;
        f.corners[4 * i + 1] = center + dx - dy;
        f.corners[4 * i + 2] = center + dx + dy;
        f.corners[4 * i + 3] = center - dx + dy;
    }
    // The side planes pass through the eye; e.g. the left one contains image_up and the left
    // edge direction forward - tan_x * right, so its outward normal is -right - tan_x * forward.
    f.planes = {
        Plane::through(position + forward * near, -forward),
        Plane::through(position + forward * far, forward),
        Plane::through(position, -right - tan_x * forward),
        Plane::through(position, right - tan_x * forward),
        Plane::through(position, -image_up - tan_y * forward),
        Plane::through(position, image_up - tan_y * forward),
    };
    return f;
}

}  // namespace shadowlab
