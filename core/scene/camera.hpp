#pragma once
// The viewer's camera (right-handed; it looks down -z of its view space): a pinhole, or an
// orthographic one whose rays are parallel (top-down, isometric and CAD views).
#include <glm/glm.hpp>

#include "geometry/frustum.hpp"

namespace shadowlab {

enum class CameraProjection { perspective, orthographic };

const char* to_string(CameraProjection projection);

// One primary ray: a ray's t along `direction` is the view depth of its point.
struct EyeRay {
    glm::dvec3 origin, direction;
};

struct Camera {
    glm::dvec3 position{0.0, 2.0, 10.0};
    glm::dvec3 target{0.0, 0.0, 0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fov_y_deg = 60.0;  // perspective
    double aspect = 16.0 / 9.0;
    double near = 0.1;
    double far = 100.0;
    CameraProjection projection = CameraProjection::perspective;
    double half_height = 1.0;  // orthographic: half the view's height in world units (glTF's ymag)

    bool is_orthographic() const { return projection == CameraProjection::orthographic; }
    glm::dvec3 view_direction() const { return glm::normalize(target - position); }
    glm::dmat4 view_matrix() const;        // world -> view
    glm::dmat4 projection_matrix() const;  // view -> OpenGL clip space
    // The same with the far plane at infinity (Everitt and Kilgard 2002): points at infinity
    // (w = 0) in front of the eye land at depth 1 instead of being clipped. An orthographic
    // camera's box is kept: its depth is linear, and a direction (w = 0) goes nowhere on the image.
    glm::dmat4 infinite_projection_matrix() const;
    // Half the view's width and height at view depth `depth`: growing with it for a pinhole, the
    // same at every depth for an orthographic camera.
    glm::dvec2 half_extent_at(double depth) const;
    // The primary ray through a normalized device point (x, y in [-1, 1]).
    EyeRay ray_through(const glm::dvec2& ndc) const;
    // The point from which `p` is seen: the eye, or p's foot on the orthographic camera's image plane.
    glm::dvec3 eye_of(const glm::dvec3& p) const;
    Frustum frustum() const;  // in world space: a box for an orthographic camera
};

}  // namespace shadowlab
