#include "scene/camera.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "math/invariant.hpp"
#include "math/normalize.hpp"

namespace shadowlab {
namespace {

// The camera's image axes in world space.
struct ImageAxes {
    glm::dvec3 forward, right, up;
};

ImageAxes image_axes(const Camera& camera) {
    const glm::dvec3 forward = camera.view_direction();
    const glm::dvec3 right = normalize_safely(glm::cross(forward, camera.up));
    return {forward, right, glm::cross(right, forward)};
}

// Half the view's extent at view depth d is offset + slope d: (0, tan) for a pinhole, (h, 0) for an
// orthographic camera.
struct ExtentLaw {
    glm::dvec2 offset, slope;
};

ExtentLaw extent_law(const Camera& camera) {
    if (camera.is_orthographic()) return {glm::dvec2(camera.aspect, 1.0) * camera.half_height, glm::dvec2(0.0)};
    const double tan_y = std::tan(glm::radians(camera.fov_y_deg) / 2.0);
    return {glm::dvec2(0.0), glm::dvec2(tan_y * camera.aspect, tan_y)};
}

}  // namespace

const char* to_string(CameraProjection projection) {
    switch (projection) {
        case CameraProjection::perspective: return "perspective";
        case CameraProjection::orthographic: return "orthographic";
    }
    return "unknown";
}

// `up` as given (a scene built in code need not normalise it): lookAt would square it.
glm::dmat4 Camera::view_matrix() const { return glm::lookAt(position, target, normalize_safely(up)); }

glm::dmat4 Camera::projection_matrix() const {
    // The loader and the camera importers refuse any other range (scene_loader.cpp, camera_import.cpp).
    assert_invariant(far > near && (is_orthographic() || near > 0.0));
    if (is_orthographic()) {
        const glm::dvec2 h = half_extent_at(near);
        return glm::ortho(-h.x, h.x, -h.y, h.y, near, far);
    }
    return glm::perspective(glm::radians(fov_y_deg), aspect, near, far);
}

glm::dmat4 Camera::infinite_projection_matrix() const {
    if (is_orthographic()) return projection_matrix();
    return glm::infinitePerspective(glm::radians(fov_y_deg), aspect, near);
}

glm::dvec2 Camera::half_extent_at(double depth) const {
    const ExtentLaw law = extent_law(*this);
    return law.offset + law.slope * depth;
}

EyeRay Camera::ray_through(const glm::dvec2& ndc) const {
    const ImageAxes axes = image_axes(*this);
    const ExtentLaw law = extent_law(*this);
    const glm::dvec2 at_offset = ndc * law.offset, per_depth = ndc * law.slope;
    return {.origin = position + axes.right * at_offset.x + axes.up * at_offset.y,
            .direction = axes.forward + axes.right * per_depth.x + axes.up * per_depth.y};
}

glm::dvec3 Camera::eye_of(const glm::dvec3& p) const {
    if (!is_orthographic()) return position;
    const glm::dvec3 forward = view_direction();
    return p - forward * glm::dot(p - position, forward);
}

// Built from the camera's axes rather than by inverting view-projection, which loses all
// precision when far / near is large.
Frustum Camera::frustum() const {
    const ImageAxes axes = image_axes(*this);
    const ExtentLaw law = extent_law(*this);

    Frustum f;
    const double distances[2] = {near, far};
    for (int i = 0; i < 2; ++i) {
        const glm::dvec3 center = position + axes.forward * distances[i];
        const glm::dvec2 half = half_extent_at(distances[i]);
        const glm::dvec3 dx = axes.right * half.x, dy = axes.up * half.y;
        f.corners[4 * i + 0] = center - dx - dy;
        f.corners[4 * i + 1] = center + dx - dy;
        f.corners[4 * i + 2] = center + dx + dy;
        f.corners[4 * i + 3] = center - dx + dy;
    }
    // A side plane passes through the eye's offset point, e.g. the left one through
    // position - offset_x right; it contains up and the left edge direction forward - slope_x right,
    // so its outward normal is -right - slope_x forward.
    const glm::dvec3 dx = axes.right * law.offset.x, dy = axes.up * law.offset.y;
    f.planes = {
        Plane::through(position + axes.forward * near, -axes.forward),
        Plane::through(position + axes.forward * far, axes.forward),
        Plane::through(position - dx, -axes.right - law.slope.x * axes.forward),
        Plane::through(position + dx, axes.right - law.slope.x * axes.forward),
        Plane::through(position - dy, -axes.up - law.slope.y * axes.forward),
        Plane::through(position + dy, axes.up - law.slope.y * axes.forward),
    };
    return f;
}

}  // namespace shadowlab
