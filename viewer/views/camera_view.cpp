// The Camera view: the scene as the camera sees it, shadowed on the GPU: by the method's own map
// (ShadowMapPass), or for a geometric technique by its polygons in the stencil buffer
// (StencilVolumePass): the shadow volume for `volumes`, and for `planar` the flattened casters
// drawn onto their plane (Blinn's projection shadows, the stencil keeping overlaps from darkening twice).
// For a map method an overlay may tint each surface by the map that serves it or by that map's
// texels per pixel (render/map_overlay.hpp), named in a legend and the caption.
#include <cstdio>

#include <vtkActor.h>
#include <vtkProperty.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderer.h>

#include "render/shadow_map_pass.hpp"
#include "render/stage_one_casters.hpp"
#include "render/stencil_volume_pass.hpp"
#include "views/space_parts.hpp"
#include "views/view_parts.hpp"

namespace shadowlab {
namespace {

// The light as both passes take it: (the direction it travels, 0) or (its position, 1).
glm::dvec4 pass_light(const Light& light) {
    return light.is_directional() ? glm::dvec4(light.direction, 0.0) : glm::dvec4(light.position, 1.0);
}

glm::dvec3 unit_colour(const Rgb& c) { return glm::dvec3(c[0], c[1], c[2]) / 255.0; }

// The texels-per-pixel ramp as the pass joins it: the Error view's heat ramp (view_parts.hpp) at
// even steps, which are its own stops, so that the GPU's ramp is the same.
std::vector<glm::vec3> texels_ramp() {
    constexpr int stops = 5;
    std::vector<glm::vec3> ramp;
    for (int k = 0; k < stops; ++k) ramp.push_back(glm::vec3(unit_colour(heat(k / (stops - 1.0)))));
    return ramp;
}

void install_map_pass(vtkRenderer* renderer, const Inspection& in, const ViewOptions& options, vtkActor* casters,
                      const std::vector<CasterActor>& material_surfaces, const Light& light) {
    vtkNew<ShadowMapPass> pass;
    pass->SetSetup(relative_to(in.setup, in.scene.camera.position), in.resolution);
    pass->SetLookup(in.lookup, light, glm::dvec3(0.0));  // the eye
    std::vector<vtkProp*> props{casters};
    for (const CasterActor& surface : material_surfaces)
        if (surface.casts) props.push_back(surface.actor);
    pass->SetCasters(props);
    // Maps that split their casters (a paraboloid's max_sagitta_texels) draw these, split as the CPU does.
    pass->SetCasterTriangles(relative_to(in.triangles, in.scene.camera.position), in.casters);
    pass->SetMaterialSurfaces(material_surfaces);
    pass->SetShadePass(vtkNew<vtkRenderStepsPass>());
    pass->SetOutput(options.lit_mask ? ShadowMapPass::Output::lit_mask : ShadowMapPass::Output::shaded);
    pass->SetOverlay(options.overlay, texels_ramp());
    renderer->SetPass(pass);
}

// "cascade 1: view depth 0.5–12.3": each map in its palette colour, with the depths it serves; a
// virtual map's pages by level.
void add_cascade_legend(vtkRenderer* renderer, const ShadowSetup& setup) {
    const MapSelection& s = setup.selection;
    std::vector<LegendEntry> entries;
    if (s.rule == MapSelection::Rule::pages) {  // a virtual map's pages, coloured by their level (ShadowMapPass)
        std::vector<int> pages_per_level(s.pages.levels.size());
        for (const PageAddress& a : s.pages.pages) ++pages_per_level.at(a.level);
        for (size_t level = 0; level < pages_per_level.size(); ++level)
            if (pages_per_level[level] > 0)
                entries.push_back(
                    {glm::dvec3(kMapPalette[level % kMapPalette.size()]),
                     "level " + std::to_string(level) + ": " + std::to_string(pages_per_level[level]) + " pages"});
        add_legend(renderer, entries);
        return;
    }
    for (size_t i = 0; i < setup.maps.size(); ++i) {
        std::string text = map_name(setup, i);
        if (s.rule == MapSelection::Rule::view_depth && i + 1 < s.split_depths.size()) {
            char depths[64];
            std::snprintf(depths, sizeof depths, ": view depth %.3g–%.3g", s.split_depths[i], s.split_depths[i + 1]);
            text += depths;
        }
        entries.push_back({glm::dvec3(kMapPalette[i]), text});
    }
    add_legend(renderer, entries);
}

void add_texels_legend(vtkRenderer* renderer) {
    std::vector<LegendEntry> entries;
    for (const auto& [texels, text] : {std::pair{8.0, "8 texels per pixel"},
                                       {2.0, "2"},
                                       {1.0, "1"},
                                       {0.5, "1/2"},
                                       {0.125, "1/8 (a texel 8 pixels wide)"}})
        entries.push_back({unit_colour(heat(texels_ramp_position(texels))), text});
    add_legend(renderer, entries);
}

void describe_overlay(vtkRenderer* renderer, const Inspection& in, MapOverlay overlay) {
    const ShadowSetup& setup = in.setup;
    if (overlay == MapOverlay::cascade_index && setup.selection.rule == MapSelection::Rule::pages) {
        // Hundreds of pages: coloured and listed by level; the Page table view shows each page and slot.
        add_cascade_legend(renderer, setup);
        add_caption(renderer, "Camera — " + in.name() + ": the level of the page serving each surface (" +
                                  std::to_string(setup.maps.size()) +
                                  " resident pages; each page and its slot: the Page table view)");
    } else if (overlay == MapOverlay::cascade_index) {
        add_cascade_legend(renderer, setup);
        char band[80] = "";
        if (setup.selection.rule == MapSelection::Rule::view_depth && setup.selection.blend_band > 0.0)
            std::snprintf(band, sizeof band, "; blend band %.2f of each split, colours crossfaded",
                          setup.selection.blend_band);
        add_caption(renderer, "Camera — " + in.name() + ": the map serving each surface (" +
                                  to_string(setup.selection.rule) + ")" + band);
    } else if (overlay == MapOverlay::texels_per_pixel) {
        add_texels_legend(renderer);
        add_caption(renderer, "Camera — " + in.name() + " " + std::to_string(in.resolution) +
                                  "²: texels per pixel of the serving map (dark: over-sampled, bright: under-sampled)");
    }
}

void install_stencil_pass(vtkRenderer* renderer, const GeometryResult& technique, const ViewOptions& options,
                          const std::vector<CasterActor>& material_surfaces, const glm::dvec3& origin,
                          const Light& light) {
    vtkNew<StencilVolumePass> pass;
    pass->SetTexturedSurfaces(material_surfaces);
    std::vector<HomogeneousPolygon> local;
    for (const HomogeneousPolygon& p : technique.stencil) local.push_back(translated(p, -origin));
    pass->SetPolygons(local, technique.rule);
    pass->SetLight(pass_light(light), glm::dvec3(0.0));  // the eye
    pass->SetOutput(options.lit_mask ? StencilVolumePass::Output::lit_mask : StencilVolumePass::Output::shaded);
    renderer->SetPass(pass);
}

// The triangles in their objects' palette colours: without those with a material, which
// material_surfaces draws.
WorldTriangles palette_triangles(const WorldTriangles& triangles) {
    if (!triangles.alpha_tested() && !triangles.coloured()) return triangles;
    WorldTriangles out{.vertices = triangles.vertices, .triangles = {}, .object = {}, .alpha = {}, .colour = {}};
    for (std::size_t i = 0; i < triangles.triangles.size(); ++i)
        if (!has_material(triangles, i)) {
            out.triangles.push_back(triangles.triangles[i]);
            out.object.push_back(triangles.object[i]);
        }
    return out;
}

// Drawn in camera-relative coordinates (the eye at 0): VTK and the GPU passes work in float32, which
// steps by 0.06 units a million units from the origin; near the eye it is as fine as anywhere.
ViewReport build_camera_view(vtkRenderer* renderer, const Inspection& in, const ViewOptions& options) {
    const glm::dvec3 origin = in.scene.camera.position;
    glm::dmat4 local_from_world(1.0);
    local_from_world[3] = glm::dvec4(-origin, 1.0);
    Camera camera = in.scene.camera;
    camera.position -= origin;
    camera.target -= origin;
    Light light = in.scene.light;
    light.position -= origin;
    const std::vector<glm::dvec3> colours = object_colours(in.scene);
    std::vector<bool> not_casting(in.casters.size());
    for (size_t i = 0; i < in.casters.size(); ++i) not_casting[i] = !in.casters[i];
    const WorldTriangles palette = palette_triangles(in.triangles);
    auto casters = actor_for(triangles_polydata(palette, in.casters, colours, local_from_world), glm::dvec3(1.0));
    auto others = actor_for(triangles_polydata(palette, not_casting, colours, local_from_world), glm::dvec3(1.0));
    // In their materials' colours; a map method's pass tests the alpha-tested ones' fragments (drawn
    // whole under a technique's).
    const std::vector<CasterActor> material_surfaces =
        shadowlab::material_surfaces(relative_to(in.triangles, in.scene.camera.position), in.casters, colours);
    std::vector<vtkActor*> surfaces{casters.Get(), others.Get()};
    for (const CasterActor& surface : material_surfaces) surfaces.push_back(surface.actor);
    for (vtkActor* actor : surfaces) {  // the passes shade them (render/surface_shading.hpp)
        actor->GetProperty()->SetAmbient(0.35);
        actor->GetProperty()->SetDiffuse(0.75);
        actor->GetProperty()->BackfaceCullingOff();
        renderer->AddActor(actor);
    }
    place_scene_camera(renderer, camera);
    renderer->SetBackground(0.62, 0.74, 0.86);
    if (in.has_map()) {
        install_map_pass(renderer, in, options, casters, material_surfaces, light);
        if (!options.lit_mask) describe_overlay(renderer, in, options.overlay);
    } else
        install_stencil_pass(renderer, *in.geometry, options, material_surfaces, origin, light);
    if (options.lit_mask) renderer->SetBackground(1.0, 0.0, 0.0);  // nothing visible: red, neither lit nor shadowed
    return {};
}

}  // namespace

View camera_view() {
    return {.name = "camera",
            .title = "Camera",
            .prepare = {},  // drawn on the GPU
            .build = build_camera_view,
            .choosers = {.overlay = true, .shadow_only = true},
            .interaction = {.through_scene_camera = true, .drag = ViewDrag::steers_scene_camera}};
}

}  // namespace shadowlab
