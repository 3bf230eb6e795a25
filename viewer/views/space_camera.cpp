// The cameras of the World, Light space and PPLS views. `from_light` looks along the light's
// direction in the space, orthographic: the picture the map is drawn from (in the World view the
// camera's view direction pointing up). `side` looks along light × view, orthographic, the light falling from the
// top: the plane of the light and the view faces the screen, and a warp shows as the camera's frustum
// turning box-like. `orbit` is the free oblique perspective camera the window starts from.
#include <algorithm>
#include <cmath>

#include <vtkCamera.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include "views/space_parts.hpp"

namespace shadowlab {
namespace {

// A unit vector perpendicular to `axis`: `wanted` made perpendicular to it, or the space's own axis
// most perpendicular to it when `wanted` runs along it.
glm::dvec3 perpendicular(const glm::dvec3& axis, const glm::dvec3& wanted) {
    const glm::dvec3 across = wanted - glm::dot(wanted, axis) * axis;
    if (glm::length(across) > 1e-3) return glm::normalize(across);
    const glm::dvec3 a = glm::abs(axis);
    const glm::dvec3 fixed = a.x <= a.y && a.x <= a.z ? glm::dvec3(1, 0, 0)
                             : a.y <= a.z             ? glm::dvec3(0, 1, 0)
                                                      : glm::dvec3(0, 0, 1);
    return glm::normalize(fixed - glm::dot(fixed, axis) * axis);
}

double window_aspect(vtkRenderer* renderer) {
    const int* size = renderer->GetRenderWindow() ? renderer->GetRenderWindow()->GetSize() : nullptr;
    return size && size[0] > 0 && size[1] > 0 ? static_cast<double>(size[0]) / size[1] : 1.0;
}

// Looking along `forward` with `up` on screen, orthographic, the box of what matters filling the view.
void look_orthographic(vtkRenderer* renderer, const Aabb& framed, const glm::dvec3& forward, const glm::dvec3& up) {
    const glm::dvec3 right = glm::cross(forward, up);
    double half_width = 0.0, half_height = 0.0;
    const glm::dvec3 centre = framed.center();
    for (const glm::dvec3& c : framed.corners()) {
        half_width = std::max(half_width, std::abs(glm::dot(c - centre, right)));
        half_height = std::max(half_height, std::abs(glm::dot(c - centre, up)));
    }
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    const glm::dvec3 eye = centre - 2.0 * framed.diagonal() * forward;
    camera->SetFocalPoint(centre.x, centre.y, centre.z);
    camera->SetPosition(eye.x, eye.y, eye.z);
    camera->SetViewUp(up.x, up.y, up.z);
    // 5% around.
    camera->SetParallelScale(1.05 * std::max({half_height, half_width / window_aspect(renderer), 1e-9}));
}

// The World view from behind, above and beside the scene camera; the light spaces from the
// light's side (their +z runs with the light), slightly tilted to show depth.
void look_oblique(vtkRenderer* renderer, const Aabb& framed, Space space, const SpaceFrame& frame) {
    // The camera's right: across its view and its image's up (an axis when it looks straight down).
    const glm::dvec3 right = glm::cross(frame.view, perpendicular(frame.view, glm::dvec3(0.0, 1.0, 0.0)));
    glm::dvec3 direction =
        space == Space::world ? frame.view + glm::dvec3(0.0, -0.8, 0.0) + 0.6 * right : glm::dvec3(0.25, 0.35, 1.0);
    direction = glm::normalize(direction);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->ParallelProjectionOff();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(-direction.x, -direction.y, -direction.z);
    camera->SetViewUp(0.0, 1.0, 0.0);
    double bounds[6] = {framed.min.x, framed.max.x, framed.min.y, framed.max.y, framed.min.z, framed.max.z};
    renderer->ResetCamera(bounds);
}

}  // namespace

void place_space_camera(vtkRenderer* renderer, const SpaceFrame& frame, SpacePreset preset, Space space) {
    const Aabb& framed = frame.clip;                    // all that is drawn: nothing runs out of the picture
    if (frame.atlas) preset = SpacePreset::from_light;  // the texture's own picture (space_frame.cpp)
    switch (preset) {
        case SpacePreset::orbit: look_oblique(renderer, framed, space, frame); break;
        case SpacePreset::from_light: {
            // In the light spaces the map's v runs along y: the picture is the map's own, u right, v up.
            const glm::dvec3 up = frame.space == Space::world ? frame.view : glm::dvec3(0.0, 1.0, 0.0);
            look_orthographic(renderer, framed, frame.light, perpendicular(frame.light, up));
            break;
        }
        case SpacePreset::side: {
            const glm::dvec3 up = -frame.light;
            look_orthographic(renderer, framed, glm::cross(up, perpendicular(frame.light, frame.view)), up);
            break;
        }
    }
    double drawn[6] = {framed.min.x, framed.max.x, framed.min.y, framed.max.y, framed.min.z, framed.max.z};
    renderer->ResetCameraClippingRange(drawn);
}

}  // namespace shadowlab
