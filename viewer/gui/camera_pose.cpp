#include "gui/camera_pose.hpp"

#include <vtkCamera.h>

namespace shadowlab {

CameraPose CameraPose::of(vtkCamera* camera) {
    const auto vec = [](const double* v) { return glm::dvec3(v[0], v[1], v[2]); };
    return {.position = vec(camera->GetPosition()),
            .focal_point = vec(camera->GetFocalPoint()),
            .view_up = vec(camera->GetViewUp()),
            .view_angle = camera->GetViewAngle(),
            .parallel_scale = camera->GetParallelScale(),
            .parallel_projection = camera->GetParallelProjection() != 0};
}

void CameraPose::apply_to(vtkCamera* camera) const {
    camera->SetPosition(position.x, position.y, position.z);
    camera->SetFocalPoint(focal_point.x, focal_point.y, focal_point.z);
    camera->SetViewUp(view_up.x, view_up.y, view_up.z);
    camera->SetViewAngle(view_angle);
    camera->SetParallelScale(parallel_scale);
    camera->SetParallelProjection(parallel_projection);
}

}  // namespace shadowlab
