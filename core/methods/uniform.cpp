// Uniform shadow map: one orthographic light projection fit to the bounds of the whole scene
// (seed 003, first post). Every view gets the same map; resolution is spread over everything.
#include "methods/uniform.hpp"

#include <cmath>

#include "methods/light_fit.hpp"
#include "methods/map_fit.hpp"
#include "methods/step_figures.hpp"

namespace shadowlab {

void fit_uniform(const ShadowInputs& in, ShadowSetup& setup, Trace* trace) {
    if (in.scene_bounds.empty()) {
        add_fallback(setup, Note{NoteKind::empty_scene, "no object to fit a map to; identity map"});
        setup.maps.push_back(ShadowMap{});
        return;
    }
    const auto c = in.scene_bounds.corners();
    const std::vector<glm::dvec3> ws_corners(c.begin(), c.end());
    record(trace, [&](Trace& t) {
        Step& step = t.add("scene-bounds", "Scene bounds", "S = union of every object's world box", Space::world)
                         .shape("S", in.scene_bounds, Role::map);
        draw_light(step, in.light, in.scene_bounds.center(), 0.25 * in.scene_bounds.diagonal());
    });
    fit_map(in, {&ws_corners, stable_up_hint(in.light.direction), in.scene_bounds.center()}, setup, trace);
    record_output(setup, ws_corners, trace);
}

ShadowSetup compute_uniform(const ShadowInputs& in, const Settings&, Trace* trace) {
    ShadowSetup setup;
    fit_uniform(in, setup, trace);
    return setup;
}

}  // namespace shadowlab
