// Drawing into a space view: one actor per shape, lines and points unlit so their colours stay the
// legend's; labels over the view, the same size on screen at any zoom.
#include <algorithm>

#include <vtkActor.h>
#include <vtkMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include "views/space_parts.hpp"

namespace shadowlab {

bool SpaceCanvas::draw(const Placed& placed, const Stroke& stroke, const std::string& legend) {
    if (placed.data->GetNumberOfCells() == 0) return false;
    auto actor = actor_for(placed, stroke.colour);
    vtkProperty* property = actor->GetProperty();
    property->SetLineWidth(static_cast<float>(stroke.width));
    property->SetPointSize(static_cast<float>(2 * stroke.width));
    property->SetOpacity(stroke.opacity);
    const bool faces = placed.data->GetNumberOfPolys() > 0 && placed.data->GetNumberOfLines() == 0;
    property->SetAmbient(faces ? 0.3 : 1.0);
    property->SetDiffuse(faces ? 0.7 : 0.0);
    // Lines and points lying on a face (a shadow polygon's outline on the ground) drawn in front of it.
    actor->GetMapper()->SetRelativeCoincidentTopologyLineOffsetParameters(0.0, -8.0);
    actor->GetMapper()->SetRelativeCoincidentTopologyPointOffsetParameter(-8.0);
    renderer_->AddActor(actor);
    list(stroke.colour, legend);
    return true;
}

void SpaceCanvas::label(const glm::dvec3& at, const std::string& text, const glm::dvec3& colour) {
    add_world_label(renderer_, at, text, 15, colour, {6, 4});  // beside the point it names, not on it
}

void SpaceCanvas::list(const glm::dvec3& colour, const std::string& legend) {
    if (legend.empty()) return;
    const bool listed =
        std::any_of(legend_.begin(), legend_.end(), [&](const LegendEntry& e) { return e.text == legend; });
    if (!listed) legend_.push_back({colour, legend});
}

}  // namespace shadowlab
