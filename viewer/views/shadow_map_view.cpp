// The Shadow map view: the depth image the method produces (near dark, far light, empty texels
// white), one screen square per texel, with the camera frustum drawn where the map puts it.
#include <algorithm>
#include <cmath>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include "views/view_parts.hpp"

namespace shadowlab {
namespace {

RgbImage depth_to_grey(const DepthMap& depth) {
    float lo = 1.0f, hi = 0.0f;
    for (float d : depth.depth)
        if (d < 1.0f) lo = std::min(lo, d), hi = std::max(hi, d);
    const float span = hi > lo ? hi - lo : 1.0f;
    const int n = depth.resolution;
    RgbImage image(n, n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const float d = depth.at(x, y);  // texel row y = v; the image's row 0 is its top: v = 1
            const double grey = d >= 1.0f ? 255.0 : 30.0 + 190.0 * (d - lo) / span;
            unsigned char* pixel = image.at(x, n - 1 - y);
            pixel[0] = pixel[1] = pixel[2] = static_cast<unsigned char>(grey);
        }
    return image;
}

// Texel edges as lines: x = k - 1/2 and y = k - 1/2 in image pixels, just above the image.
Placed texel_grid(int n) {
    std::vector<std::pair<glm::dvec3, glm::dvec3>> lines;
    for (int k = 0; k <= n; ++k) {
        lines.push_back({{k - 0.5, -0.5, 0.5}, {k - 0.5, n - 0.5, 0.5}});
        lines.push_back({{-0.5, k - 0.5, 0.5}, {n - 0.5, k - 0.5, 0.5}});
    }
    return segments_polydata(lines, glm::dmat4(1.0));
}

// Before each render: the grid shows once a texel spans at least 8 screen pixels (zoomed in).
class TexelGridToggle : public vtkCommand {
public:
    static TexelGridToggle* New() { return new TexelGridToggle; }
    vtkSmartPointer<vtkActor> grid;
    void Execute(vtkObject* caller, unsigned long, void*) override {
        auto* renderer = static_cast<vtkRenderer*>(caller);
        const double pixels_per_texel = renderer->GetSize()[1] / (2.0 * renderer->GetActiveCamera()->GetParallelScale());
        grid->SetVisibility(pixels_per_texel >= 8.0);
    }
};

}  // namespace

ViewReport build_shadow_map_view(vtkRenderer* renderer, const Inspection& in) {
    const int n = in.resolution;
    renderer->SetBackground(0.12, 0.13, 0.16);
    if (!in.has_map()) {
        add_caption(renderer, in.title() + ": no shadow map (a geometric technique; see the Stencil count view)");
        return {};
    }
    show_image(renderer, depth_to_grey(in.depth));
    // World -> image pixels: texel (x, y) is centred at pixel (x, y) of the image actor.
    glm::dmat4 to_pixels(1.0);
    to_pixels[0][0] = to_pixels[1][1] = n;
    to_pixels[3] = glm::dvec4(-0.5, -0.5, 0.0, 1.0);
    to_pixels[2][2] = 0.0;
    to_pixels[3][2] = 1.0;  // drawn just above the image
    auto frustum = actor_for(geometry_polydata(in.inputs.frustum, to_pixels * in.map().world_to_uvz), glm::dvec3(1.0, 0.85, 0.1));
    frustum->GetProperty()->SetLineWidth(2.0f);
    renderer->AddActor(frustum);
    vtkNew<TexelGridToggle> toggle;
    toggle->grid = actor_for(texel_grid(n), glm::dvec3(0.35, 0.55, 0.85));
    renderer->AddActor(toggle->grid);
    renderer->AddObserver(vtkCommand::StartEvent, toggle);
    add_caption(renderer, "Shadow map " + std::to_string(n) + "² — " + in.name() +
                              " (camera frustum in yellow; texel grid when zoomed in)");
    return {};
}

}  // namespace shadowlab
