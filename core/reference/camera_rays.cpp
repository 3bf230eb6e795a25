#include "reference/camera_rays.hpp"

namespace shadowlab {

CameraRays::CameraRays(const Camera& camera, int width, int height)
    : width_(width),
      height_(height),
      eye_(camera.position),
      forward_(camera.view_direction()),
      view_to_world_(glm::inverse(camera.view_matrix())) {
    const glm::dmat4 projection = camera.projection_matrix();
    focal_x_ = projection[0][0];
    focal_y_ = projection[1][1];
}

glm::dvec3 CameraRays::direction(int x, int y) const {
    const double ndc_x = 2.0 * (x + 0.5) / width_ - 1.0, ndc_y = 1.0 - 2.0 * (y + 0.5) / height_;
    return view_to_world_ * glm::dvec3(ndc_x / focal_x_, ndc_y / focal_y_, -1.0);
}

glm::dvec2 CameraRays::pixel_of_ndc(const glm::dvec2& ndc) const {
    return {(ndc.x + 1.0) * width_ / 2.0 - 0.5, (1.0 - ndc.y) * height_ / 2.0 - 0.5};
}

}  // namespace shadowlab
