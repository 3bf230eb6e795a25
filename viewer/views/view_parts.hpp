#pragma once
// One descriptor per view (views/*_view.cpp, listed in view_registry.cpp), and what they share.
#include <array>
#include <vector>
#include <glm/glm.hpp>
#include <vtkSmartPointer.h>

#include "render/rgb_image.hpp"
#include "views/polydata.hpp"
#include "views/view.hpp"

class vtkActor;
class vtkRenderer;
class vtkTextProperty;

namespace shadowlab {

View camera_view();
View world_view();        // space_view.cpp
View light_space_view();  // space_view.cpp
View ppls_view();         // space_view.cpp
View shadow_map_view();
View texels_view();
View error_view();
View stencil_view();
View page_table_view();  // page_table_view.cpp
View difference_view();  // difference_view.cpp
View flatland_view();    // flatland_view.cpp

// The camera image the Error view judges (a technique's own; for a map, options.width x height).
glm::ivec2 judged_image_size(const Inspection& in, const ViewOptions& options);

// The Texels view's back-projection (texels_view.cpp), from Inspection::surface_depth: where each
// texel lands on the scene's surfaces. A texel of a linear map or a cube face carried back to the world point its depth
// puts it at.
struct WorldTexel {
    int map = 0;                        // its index in the setup
    glm::ivec2 texel{0};                // in the texture
    glm::dvec3 centre{0.0};             // the texel's centre, on the surface it samples
    std::array<glm::dvec3, 4> corners;  // its footprint on that surface, around (u, v): the depth's slope to
                                        // the neighbours carried to the texel's corners (affine over a plane)
};
// Every `stride`-th texel in u and v of each tile that holds a surface (neither the clear value 1 nor
// a surface before the near plane, clamped to 0) where the setup's selection gives its map (a
// cascade's texels in its own split); paraboloid maps are left out (their texels' edges bend).
std::vector<WorldTexel> world_texels(const ShadowSetup& setup, const DepthMap& depth, int stride);
// The least stride at which at most `most` of the texels holding a surface are taken, before the
// selection: world_texels gives no more.
int texel_stride(const ShadowSetup& setup, const DepthMap& depth, size_t most);
// The Shadow map view's tile borders and labels, drawn when the texture holds several maps.
extern const glm::dvec3 kTileBorder;

// Shared by the builders.
vtkSmartPointer<vtkActor> actor_for(const Placed& placed, const glm::dvec3& colour);
void place_scene_camera(vtkRenderer* renderer, const Camera& camera);  // the VTK camera = the scene's
void show_image(vtkRenderer* renderer, const RgbImage& image);         // one screen square per pixel, crisp
void add_caption(vtkRenderer* renderer, const std::string& text);
// A label pinned to the world point `at`, `display_offset` pixels beside it, drawn over the view
// (world_label.cpp: not a billboard in the scene, whose translucency would cost the view an extra pass).
void add_world_label(vtkRenderer* renderer, const glm::dvec3& at, const std::string& text, int size,
                     const glm::dvec3& colour, const glm::ivec2& display_offset);
// Text over a view: a font with γ, ³ and × where one is installed, `size` points, `colour` on a
// translucent black backing that keeps it legible over any picture.
void style_overlay_text(vtkTextProperty* text, int size, const glm::dvec3& colour = glm::dvec3(1.0));
// How the views name map i (from 0) of a setup: "cascade 2" for maps chosen by view depth, else "map 2".
std::string map_name(const ShadowSetup& setup, size_t i);
using Rgb = std::array<unsigned char, 3>;
Rgb heat(double t);  // an inferno-like ramp over t in [0, 1]
// The 3x3 block around pixel i (row-major), so that a lone pixel is seen (the Error and Difference views).
void fill_block(RgbImage& image, size_t i, const Rgb& colour);

}  // namespace shadowlab
