// Uniform shadow map: one orthographic light projection fit to the bounds of the whole scene
// (seed 003, first post). Every view gets the same map; resolution is spread over everything.
#include "methods/uniform.hpp"

#include <cmath>

#include "methods/map_fit.hpp"

namespace shadowlab {

// A fixed up hint (world +y, or +x for a vertical light) keeps the map still as the camera moves.
static glm::dvec3 stable_up(const glm::dvec3& light_direction) {
    return std::abs(light_direction.y) < 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
}

void fit_uniform(const ShadowInputs& in, ShadowSetup& setup, Trace* trace) {
    if (in.scene_bounds.empty()) {
        add_fallback(setup, "empty scene: no object to fit a map to; identity map");
        setup.maps.push_back(ShadowMap{});
        return;
    }
    const auto c = in.scene_bounds.corners();
    const std::vector<glm::dvec3> corners(c.begin(), c.end());
    record(trace, [&](Trace& t) {
        t.add("scene-bounds", "Scene bounds", "S = union of every object's world box", Space::world)
            .shape("S", in.scene_bounds);
    });
    fit_map(in, {&corners, stable_up(in.light.direction), in.scene_bounds.center()}, setup, trace);
    record_output(setup, corners, trace);
}

ShadowSetup compute_uniform(const ShadowInputs& in, const Settings&, Trace* trace) {
    ShadowSetup setup;
    fit_uniform(in, setup, trace);
    return setup;
}

}  // namespace shadowlab
