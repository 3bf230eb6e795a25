// The Shadow map view: the depth image the method produces (near dark, far light, empty texels
// white), one screen square per texel, with the camera frustum drawn where the map puts it.
#include <algorithm>
#include <cmath>

#include <vtkActor.h>
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
    add_caption(renderer, "Shadow map " + std::to_string(n) + "² — " + in.name() + " (camera frustum in yellow)");
    return {};
}

}  // namespace shadowlab
