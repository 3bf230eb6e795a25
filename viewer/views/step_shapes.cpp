// A trace's steps in a space view: each step's shapes carried from the step's space into the view's
// and cut to its clip box. The chosen step is bright, in its roles' colours, with thick lines and
// its labels; what earlier steps built stays, dimmed and thin, so the construction reads in order.
// Translucent faces get crisp outlines in the same colour.
#include <variant>

#include "views/space_parts.hpp"

namespace shadowlab {
namespace {

const glm::dvec3 kEarlierStep{0.55, 0.62, 0.78};
const char* const kEarlierLegend = "earlier steps";

Stroke stroke_for(const NamedGeometry& g, bool current) {
    const bool faces =
        std::holds_alternative<ConvexPolyhedron>(g.geometry) || std::holds_alternative<PolygonSet>(g.geometry);
    // Silhouette edges stay thick after their step: they lie on the meshes' own edges.
    const bool edges = std::holds_alternative<SegmentSet>(g.geometry);
    const glm::dvec3 earlier = g.role == Role::step && g.map < 0 ? kEarlierStep : dimmed(shape_colour(g));
    return {.colour = current ? shape_colour(g) : earlier,
            .width = current ? (edges ? 5.0 : 3.5) : (edges ? 3.0 : 1.5),
            .opacity = faces ? (current ? 0.35 : 0.08) : 1.0};  // earlier faces faint: several overlap
}

void draw_shape(SpaceCanvas& canvas, const NamedGeometry& g, const ShadowSetup& setup, const Placement& placement,
                bool current) {
    const Stroke stroke = stroke_for(g, current);
    const bool drawn =
        canvas.draw(geometry_polydata(g.geometry, placement), stroke, current ? shape_legend(g, setup) : "");
    if (const auto outline = outline_polydata(g.geometry, placement))
        canvas.draw(*outline, {.colour = stroke.colour, .width = current ? 2.5 : 1.0}, "");
    if (drawn && !current) canvas.list(kEarlierStep, kEarlierLegend);
    const auto* label = std::get_if<Label>(&g.geometry);
    if (!current || !drawn || !label) return;
    if (const auto at = placed_point(placement, label->at)) canvas.label(*at, label->text, stroke.colour);
}

}  // namespace

void draw_steps(SpaceCanvas& canvas, const Inspection& in, size_t from, size_t to, size_t chosen) {
    const std::vector<Step>& steps = in.trace.steps();
    const bool atlas = unit_space_is_an_atlas(in, canvas.frame().space);  // only its own steps can be drawn there
    for (size_t i = from; i < to && i < steps.size(); ++i) {
        const auto step_from_world = world_to(in, steps[i].space);
        if (!step_from_world || (atlas && steps[i].space != Space::unit)) continue;
        Placement placement = canvas.frame().placement_from(*step_from_world);
        placement.reach = in.inputs.scene_bounds.diagonal();  // a shadow volume's vertices at infinity
        for (const NamedGeometry& g : steps[i].geometry) draw_shape(canvas, g, in.setup, placement, i == chosen);
    }
}

}  // namespace shadowlab
