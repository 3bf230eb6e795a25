#include "reference/camera_rays.hpp"

namespace shadowlab {

CameraRays::CameraRays(const Camera& camera, int width, int height)
    : camera_(camera), width_(width), height_(height), forward_(camera.view_direction()) {}

EyeRay CameraRays::ray(int x, int y) const {
    return camera_.ray_through({2.0 * (x + 0.5) / width_ - 1.0, 1.0 - 2.0 * (y + 0.5) / height_});
}

glm::dvec2 CameraRays::pixel_of_ndc(const glm::dvec2& ndc) const {
    return {(ndc.x + 1.0) * width_ / 2.0 - 0.5, (1.0 - ndc.y) * height_ / 2.0 - 0.5};
}

}  // namespace shadowlab
