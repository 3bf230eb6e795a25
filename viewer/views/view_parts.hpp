#pragma once
// One builder per view (views/*_view.cpp), dispatched by build_view.
#include <array>
#include <glm/glm.hpp>
#include <vtkSmartPointer.h>

#include "render/rgb_image.hpp"
#include "views/polydata.hpp"
#include "views/view.hpp"

class vtkActor;
class vtkRenderer;
class vtkTextProperty;

namespace shadowlab {

ViewReport build_camera_view(vtkRenderer* renderer, const Inspection& in, const ViewOptions& options);
ViewReport build_space_view(vtkRenderer* renderer, const Inspection& in, ViewKind view, const ViewOptions& options);
ViewReport build_shadow_map_view(vtkRenderer* renderer, const Inspection& in);
ViewReport build_error_view(vtkRenderer* renderer, const Inspection& in, const ViewOptions& options);
ViewReport build_stencil_view(vtkRenderer* renderer, const Inspection& in);

// Shared by the builders.
vtkSmartPointer<vtkActor> actor_for(const Placed& placed, const glm::dvec3& colour);
void place_scene_camera(vtkRenderer* renderer, const Camera& camera);  // the VTK camera = the scene's
void show_image(vtkRenderer* renderer, const RgbImage& image);  // one screen square per pixel, crisp
void add_caption(vtkRenderer* renderer, const std::string& text);
// Text over a view: a font with γ, ³ and × where one is installed, `size` points, `colour` on a
// translucent black backing that keeps it legible over any picture.
void style_overlay_text(vtkTextProperty* text, int size, const glm::dvec3& colour = glm::dvec3(1.0));
using Rgb = std::array<unsigned char, 3>;
Rgb heat(double t);  // an inferno-like ramp over t in [0, 1]

}  // namespace shadowlab
