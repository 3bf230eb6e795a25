// A label pinned to a world point and drawn over the view, the same size at any zoom. It is a 2D
// overlay, not a billboard in the scene: a billboard's text is translucent geometry, and one piece
// of translucent geometry makes VTK run its order-independent translucency pass over the whole
// view (under a software OpenGL a third of a World view's render); over the view, a label also
// stays legible where geometry stands in front of its point. While its point is behind the camera,
// where a projection would mirror it into view, it is hidden.
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCoordinate.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>

#include "views/view_parts.hpp"

namespace shadowlab {
namespace {

bool in_front_of_camera(vtkRenderer* renderer, const double* world) {
    vtkCamera* camera = renderer->GetActiveCamera();
    const double* eye = camera->GetPosition();
    const double* forward = camera->GetDirectionOfProjection();
    double along = 0.0;
    for (int axis = 0; axis < 3; ++axis) along += (world[axis] - eye[axis]) * forward[axis];
    return camera->GetParallelProjection() || along > 0.0;
}

}  // namespace

void add_world_label(vtkRenderer* renderer, const glm::dvec3& at, const std::string& text, int size,
                     const glm::dvec3& colour, const glm::ivec2& display_offset) {
    vtkNew<vtkCoordinate> anchor;
    anchor->SetCoordinateSystemToWorld();
    anchor->SetValue(at.x, at.y, at.z);
    vtkNew<vtkTextActor> label;
    label->SetInput(text.c_str());
    label->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
    label->GetPositionCoordinate()->SetReferenceCoordinate(anchor);
    label->GetPositionCoordinate()->SetValue(display_offset.x, display_offset.y);
    style_overlay_text(label->GetTextProperty(), size, colour);
    renderer->AddViewProp(label);

    vtkNew<vtkCallbackCommand> hide_behind;
    hide_behind->SetClientData(label.GetPointer());
    hide_behind->SetCallback([](vtkObject* caller, unsigned long, void* label, void*) {
        auto* actor = static_cast<vtkTextActor*>(label);
        const double* world = actor->GetPositionCoordinate()->GetReferenceCoordinate()->GetValue();
        actor->SetVisibility(in_front_of_camera(static_cast<vtkRenderer*>(caller), world));
    });
    renderer->AddObserver(vtkCommand::StartEvent, hide_behind);
}

}  // namespace shadowlab
