#pragma once
// The camera's primary rays, one through each pixel centre (row 0 at the top of the image), shared
// by the exact reference and the geometric techniques so that both judge the same points: from the
// eye for a pinhole, parallel along the view direction for an orthographic camera.
#include <glm/glm.hpp>

#include "scene/camera.hpp"

namespace shadowlab {

class CameraRays {
public:
    CameraRays(const Camera& camera, int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }
    // The world ray through pixel (x, y), scaled so that a ray's t along it is the view depth.
    EyeRay ray(int x, int y) const;
    // The view depth of a world point: its t along its pixel's ray.
    double view_depth(const glm::dvec3& p) const { return glm::dot(p - camera_.position, forward_); }
    // Continuous pixel coordinates of a normalized device point (x, y in [-1, 1]); pixel centres
    // sit at integers.
    glm::dvec2 pixel_of_ndc(const glm::dvec2& ndc) const;

private:
    Camera camera_;
    int width_, height_;
    glm::dvec3 forward_;
};

}  // namespace shadowlab
