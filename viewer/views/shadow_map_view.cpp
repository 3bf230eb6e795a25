// The Shadow map view: the depth image the method produces (near dark, far light, empty texels
// white), one screen square per texel, with the camera frustum drawn where the map puts it; a
// texture of several maps (an atlas of cascades) with each tile's border and its label.
#include <algorithm>
#include <cmath>

#include <vtkActor.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextProperty.h>

#include "maps/map_lookup.hpp"
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

// World -> image pixels of the texture for one map: its texel (x, y) is centred at pixel (x, y) of
// the image actor, its tile where the viewport puts it; drawn just above the image.
// The map's tile in texture pixels, around the drawing plane z = 1.
Aabb tile_in_pixels(const ShadowMap& map, int n) {
    return {{map.viewport.x * n - 0.5, map.viewport.y * n - 0.5, 0.5}, {map.viewport.z * n - 0.5, map.viewport.w * n - 0.5, 1.5}};
}

glm::dmat4 pixels_from_world(const ShadowMap& map, int n) {
    glm::dmat4 pixels_from_uvz(1.0);
    pixels_from_uvz[0][0] = (map.viewport.z - map.viewport.x) * n;
    pixels_from_uvz[1][1] = (map.viewport.w - map.viewport.y) * n;
    pixels_from_uvz[2][2] = 0.0;
    pixels_from_uvz[3] = glm::dvec4(map.viewport.x * n - 0.5, map.viewport.y * n - 0.5, 1.0, 1.0);
    return pixels_from_uvz * map.world_to_uvz;
}

// Each tile's border, its edges through the texel edges the viewport names, and a label inside its
// top-left corner on two lines, so that it fits a small tile: "cascade 2" (for maps chosen by view
// depth; "map 2" otherwise) over "1024²".
void draw_tiles(vtkRenderer* renderer, const ShadowSetup& setup, int n) {
    std::vector<std::pair<glm::dvec3, glm::dvec3>> edges;
    for (size_t i = 0; i < setup.maps.size(); ++i) {
        const Aabb tile = tile_in_pixels(setup.maps[i], n);
        const glm::dvec3 a(tile.min.x, tile.min.y, 0.6), b(tile.max.x, tile.min.y, 0.6), c(tile.max.x, tile.max.y, 0.6),
            d(tile.min.x, tile.max.y, 0.6);
        for (const auto& edge : {std::pair{a, b}, std::pair{b, c}, std::pair{c, d}, std::pair{d, a}}) edges.push_back(edge);
        const auto side = static_cast<int>(std::lround(tile_resolution(setup.maps[i], n)));
        const std::string text = map_name(setup, i) + "\n" + std::to_string(side) + "²";
        vtkNew<vtkBillboardTextActor3D> label;
        label->SetInput(text.c_str());
        label->SetPosition(d.x, d.y, d.z);
        label->SetDisplayOffset(6, -40);  // inside the tile, below its top edge
        style_overlay_text(label->GetTextProperty(), 14, kTileBorder);
        renderer->AddViewProp(label);
    }
    auto borders = actor_for(segments_polydata(edges, glm::dmat4(1.0)), kTileBorder);
    borders->GetProperty()->SetLineWidth(2.0f);
    renderer->AddActor(borders);
}

}  // namespace

const glm::dvec3 kTileBorder{0.2, 0.9, 0.5};

ViewReport build_shadow_map_view(vtkRenderer* renderer, const Inspection& in) {
    const int n = in.resolution;
    renderer->SetBackground(0.12, 0.13, 0.16);
    if (!in.has_map()) {
        add_caption(renderer, in.title() + ": no shadow map (a geometric technique; see the Stencil count view)");
        return {};
    }
    ViewReport report;
    show_image(renderer, depth_to_grey(in.depth));
    for (const ShadowMap& map : in.setup.maps) {  // the camera frustum where each linear map puts it
        if (map.projection == Projection::paraboloid) {
            report.notes.push_back("the camera frustum is not drawn on a paraboloid map (its edges bend)");
            continue;
        }
        // Cut to the map's tile: what lies outside the map is not in it.
        const Placement in_tile{.to_space = pixels_from_world(map, n), .clip = tile_in_pixels(map, n)};
        auto frustum = actor_for(geometry_polydata(in.inputs.frustum, in_tile), glm::dvec3(1.0, 0.85, 0.1));
        frustum->GetProperty()->SetLineWidth(2.0f);
        renderer->AddActor(frustum);
    }
    if (in.setup.maps.size() > 1) draw_tiles(renderer, in.setup, n);
    vtkNew<TexelGridToggle> toggle;
    toggle->grid = actor_for(texel_grid(n), glm::dvec3(0.35, 0.55, 0.85));
    renderer->AddActor(toggle->grid);
    renderer->AddObserver(vtkCommand::StartEvent, toggle);
    const std::string maps = in.setup.maps.size() > 1 ? ", " + std::to_string(in.setup.maps.size()) + " maps in tiles" : "";
    add_caption(renderer, "Shadow map " + std::to_string(n) + "² — " + in.name() + maps +
                              " (camera frustum in yellow; " + (in.setup.maps.size() > 1 ? "tile borders in green; " : "") +
                              "texel grid when zoomed in)");
    return report;
}

}  // namespace shadowlab
