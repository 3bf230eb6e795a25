// The World, Light space and PPLS views: the scene, the camera's frustum, the map's volume, the light
// and the space's axes, and the method's steps, all carried into one space by the method's own
// frames and cut to the region that matters there plus a margin (space_frame.cpp). The chosen step
// is drawn bright in its roles' colours, earlier steps dimmed; a legend names what is drawn, and the
// caption says which step it is, its formula and its values. A geometric technique has no map and
// no light spaces: the World view shows its steps.
#include <algorithm>
#include <stdexcept>
#include <string>

#include <vtkRenderer.h>

#include "io/value_text.hpp"
#include "maps/projection_kind.hpp"
#include "views/space_parts.hpp"

namespace shadowlab {
namespace {

const glm::dvec3 kMissed{1.0, 0.2, 0.8}, kAxes{0.75, 0.75, 0.75};

// The space views: each draws in one space of the method.
const char* space_view_title(Space space) {
    switch (space) {
        case Space::world: return "World";
        case Space::light: return "Light space";
        case Space::ppls: return "PPLS";
        default: throw std::logic_error(std::string("no view draws in ") + to_string(space) + " space");
    }
}

// A light inside the scene's bounds (a lamp in a room): walls around it would hide every step.
bool light_indoors(const Scene& scene) {
    return !scene.light.is_directional() && scene.bounds().contains(scene.light.position);
}

// The scene's triangles, cut to the frame's clip box (in PPLS, points near w = 0 would otherwise
// fly off toward infinity); opaque in the World unless the light is indoors, translucent where the
// step shapes matter more.
void draw_scene(SpaceCanvas& canvas, const Inspection& in, Space space, const ViewOptions& options) {
    if (space == Space::ppls && !options.scene_in_ppls) return;
    const Placed scene = triangles_polydata(in.triangles, std::vector<bool>(in.scene.objects.size(), true),
                                            object_colours(in.scene), canvas.frame().placement_from(glm::dmat4(1.0)));
    const bool opaque = space == Space::world && !light_indoors(in.scene);
    canvas.draw(scene, {.colour = glm::dvec3(1.0), .opacity = opaque ? 1.0 : 0.35}, "");
}

// Every linear map's volume (a cascade's maps side by side), labelled at its far corner. More maps
// than the palette has colours (a virtual map's hundreds of pages) are drawn thin and dimmed, with
// no labels, so that the steps' own shapes stay legible over them.
void draw_map_volumes(SpaceCanvas& canvas, const ShadowSetup& setup, ViewReport& report) {
    const Placement placement = canvas.frame().placement_from(glm::dmat4(1.0));
    const RoleStyle& map = role_style(Role::map);
    const bool many = setup.maps.size() > kMapPalette.size();
    const Stroke stroke{.colour = many ? dimmed(map.colour) : map.colour, .width = many ? 1.0 : 2.0};
    const std::string legend =
        many ? std::string(map.legend) + ", " + std::to_string(setup.maps.size()) + " maps" : std::string(map.legend);
    for (const ShadowMap& m : setup.maps) {
        if (!projection_kind(m).projective()) {
            report.notes.push_back(std::string("a ") + projection_kind(m).name +
                                   " map has no box-shaped volume: not drawn");
            continue;
        }
        const Frustum volume = map_volume(m);
        canvas.draw(geometry_polydata(volume, placement), stroke, legend);
        if (many) continue;
        if (const auto corner = placed_point(placement, volume.corners[6])) canvas.label(*corner, "[0,1]³", map.colour);
    }
}

// The light as an arrow entering the region along its direction in the space, and the space's own
// axes x, y, z from the region's lowest corner.
void draw_light_and_axes(SpaceCanvas& canvas) {
    const SpaceFrame& frame = canvas.frame();
    const Placement in_space{.clip = frame.clip, .head = frame.arrow_head()};
    const RoleStyle& light = role_style(Role::light);
    canvas.draw(geometry_polydata(Arrow{frame.light_from, frame.light_to}, in_space),
                {.colour = light.colour, .width = 3.0}, light.legend);
    canvas.label(0.5 * (frame.light_from + frame.light_to), "light", light.colour);
    const double length = 0.15 * frame.scale();
    const char* names[3] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 tip = frame.region.min;
        tip[axis] += length;
        canvas.draw(geometry_polydata(Arrow{frame.region.min, tip}, in_space), {.colour = kAxes, .width = 2.0},
                    std::string(to_string(frame.space)) + " axes");
        canvas.label(tip, names[axis], kAxes);
    }
}

void draw_input_boxes(SpaceCanvas& canvas, const std::vector<Aabb>& boxes, Role role) {
    canvas.draw(boxes_polydata(boxes, canvas.frame().placement_from(glm::dmat4(1.0))),
                {.colour = role_style(role).colour, .width = 1.0}, role_style(role).legend);
}

// The visible points the map misses where they are in shadow (the map leaves them wrongly lit),
// marked. Those lit anyway are only counted: a focused or warped map leaves out, by design, what no
// caster can shadow, and marking them would cover the picture. The counts are said even when 0.
void draw_missed_points(SpaceCanvas& canvas, const Inspection& in) {
    const MissedPoints missed = visible_points_missed(in);
    const Placement placement = canvas.frame().placement_from(glm::dmat4(1.0));
    canvas.draw(points_polydata(missed.in_shadow, placement), {.colour = kMissed, .width = 3.5}, "");
    canvas.list(kMissed, "outside the map: " + std::to_string(missed.count()) + " seen, " +
                             std::to_string(missed.in_shadow.size()) + " in shadow");
}

// What the steps are drawn over: the scene, the camera's frustum, the maps' volumes, the input
// boxes (World), the light and the space's axes.
void draw_context(SpaceCanvas& canvas, const Inspection& in, Space space, const ViewOptions& options,
                  ViewReport& report) {
    draw_scene(canvas, in, space, options);
    const RoleStyle& camera = role_style(Role::view);
    canvas.draw(geometry_polydata(in.inputs.frustum, canvas.frame().placement_from(glm::dmat4(1.0))),
                {.colour = camera.colour}, camera.legend);
    if (in.has_map()) draw_map_volumes(canvas, in.setup, report);
    if (space == Space::world) {
        draw_input_boxes(canvas, in.inputs.casters, Role::casters);
        draw_input_boxes(canvas, in.inputs.receivers, Role::receivers);
    }
    draw_light_and_axes(canvas);
}

// The index of the chosen step (the last one by default); the step count when none was recorded.
size_t chosen_step(const Trace& trace, const std::string& id) {
    const std::vector<Step>& steps = trace.steps();
    if (id.empty()) return steps.empty() ? 0 : steps.size() - 1;
    size_t i = 0;
    while (i < steps.size() && steps[i].id != id) ++i;
    return i;
}

// The step's values as text: scalars, vectors and strings with their values, matrices only named.
std::string values_text(const Step& step) {
    std::string values, matrices;
    for (const NamedValue& v : step.values) {
        std::string& line = std::holds_alternative<glm::dmat4>(v.value) ? matrices : values;
        if (!line.empty()) line += "   ";
        line += std::holds_alternative<glm::dmat4>(v.value) ? v.name : v.name + " = " + value_text(v.value);
    }
    if (matrices.empty()) return values;
    if (!values.empty()) values += '\n';
    return values + "matrices: " + matrices;
}

// "PPLS · lispsm · Step 8 of 10 · Perspective warp P", the step's formula, its values.
std::string caption(const Inspection& in, Space space, const SpaceFrame& frame, const ViewOptions& options,
                    size_t chosen) {
    std::string title = space_view_title(space);
    const bool masked =
        std::any_of(in.setup.maps.begin(), in.setup.maps.end(), [](const ShadowMap& m) { return !m.mask.empty(); });
    if (frame.atlas)
        title += masked ? " (the atlas: maps sharing one texture, each in its mask)"
                        : " (the atlas: paraboloids reach it by no matrix)";
    else if (space == Space::ppls && frame.space == Space::unit)
        title += " (no warp: the map's unit space)";
    title += std::string(" · ") + in.name() + " · " + to_string(options.preset);
    const std::vector<Step>& steps = in.trace.steps();
    if (chosen >= steps.size()) return title + " · no steps recorded";
    const Step& step = steps[chosen];
    std::string text = title + " · Step " + std::to_string(chosen + 1) + " of " + std::to_string(steps.size()) + " · " +
                       step.title + '\n' + step.explanation;
    if (const std::string values = values_text(step); !values.empty()) text += '\n' + values;
    return text;
}

ViewReport build_space_view(vtkRenderer* renderer, const Inspection& in, Space space, const ViewOptions& options) {
    ViewReport report;
    renderer->SetBackground(kSpaceBackground.r, kSpaceBackground.g, kSpaceBackground.b);
    const size_t chosen = chosen_step(in.trace, options.step);
    const std::vector<Step>& steps = in.trace.steps();
    const std::optional<SpaceFrame> frame = space_frame(in, space, chosen < steps.size() ? &steps[chosen] : nullptr);
    if (!frame) {
        add_caption(renderer,
                    in.title() + ": no " + space_view_title(space) +
                        (in.has_map() ? " (the method has no such space)"
                                      : " (a geometric technique: no light space, no map; see the World view)"));
        return report;
    }
    // Drawn in layers, each over the one before where lines coincide: what earlier steps built,
    // the context (scene, frustum, map, light, axes), the chosen step.
    SpaceCanvas canvas(renderer, *frame);
    draw_steps(canvas, in, 0, chosen, chosen);
    const bool world_context = !unit_space_is_an_atlas(in, frame->space);
    if (world_context) draw_context(canvas, in, space, options, report);
    draw_steps(canvas, in, chosen, chosen + 1, chosen);
    if (world_context && in.has_map()) draw_missed_points(canvas, in);
    canvas.finish();
    report.legend = canvas.legend();
    place_space_camera(renderer, *frame, options.preset, space);
    add_caption(renderer, caption(in, space, *frame, options, chosen));
    return report;
}

// One descriptor for the three: they differ in their space, PPLS also in the scene it may leave out.
View space_view(const char* name, Space space, ViewChoosers choosers) {
    return {.name = name,
            .title = space_view_title(space),
            .prepare =
                [](const Inspection& in, const ViewOptions&) {
                    if (in.has_map()) visible_points_missed(in);  // marked where they are in shadow
                },
            .build = [space](vtkRenderer* renderer, const Inspection& in,
                             const ViewOptions& options) { return build_space_view(renderer, in, space, options); },
            .choosers = choosers,
            .interaction = {.draws_steps = true, .drag = ViewDrag::orbits_kept, .handles = space == Space::world}};
}

}  // namespace

View world_view() { return space_view("world", Space::world, {.preset = true}); }
View light_space_view() { return space_view("light", Space::light, {.preset = true}); }
View ppls_view() { return space_view("ppls", Space::ppls, {.preset = true, .scene_in_ppls = true}); }

}  // namespace shadowlab
