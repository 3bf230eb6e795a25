#pragma once
// The camera's eye rays, one through each pixel centre (row 0 at the top of the image), shared by
// the exact reference and the geometric techniques so that both judge the same points.
#include <glm/glm.hpp>

#include "scene/camera.hpp"

namespace shadowlab {

class CameraRays {
public:
    CameraRays(const Camera& camera, int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }
    const glm::dvec3& eye() const { return eye_; }
    // World direction through pixel (x, y), scaled so that a ray's t along it is the view depth.
    glm::dvec3 direction(int x, int y) const;
    // The view depth of a world point: its t along its pixel's ray.
    double view_depth(const glm::dvec3& p) const { return glm::dot(p - eye_, forward_); }
    // Continuous pixel coordinates of a normalized device point (x, y in [-1, 1]); pixel centres
    // sit at integers.
    glm::dvec2 pixel_of_ndc(const glm::dvec2& ndc) const;

private:
    int width_, height_;
    glm::dvec3 eye_, forward_;
    glm::dmat3 view_to_world_;  // a rotation: t stays the view depth
    double focal_x_, focal_y_;  // the projection's scale of x and y
};

}  // namespace shadowlab
