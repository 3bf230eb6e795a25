#pragma once
// Where a panel's vtkCamera stands and how it projects: kept when the user leaves an orbit in a
// World, Light space or PPLS panel, and put back when the panel draws the same view with the same
// preset again (another step, method or light), in place of the view's default camera.
#include <glm/glm.hpp>

class vtkCamera;

namespace shadowlab {

struct CameraPose {
    glm::dvec3 position{0.0};
    glm::dvec3 focal_point{0.0};
    glm::dvec3 view_up{0.0, 1.0, 0.0};
    double view_angle = 30.0;     // degrees, perspective
    double parallel_scale = 1.0;  // half the height seen, orthographic
    bool parallel_projection = false;

    static CameraPose of(vtkCamera* camera);
    void apply_to(vtkCamera* camera) const;
};

}  // namespace shadowlab
