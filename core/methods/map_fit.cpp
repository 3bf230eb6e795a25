#include "methods/map_fit.hpp"

#include <cmath>

#include "maps/projection_kind.hpp"
#include "methods/light_fit.hpp"
#include "methods/step_figures.hpp"

namespace shadowlab {

void add_fallback(ShadowSetup& setup, Note fallback) { setup.fallbacks.push_back(std::move(fallback)); }

static void fit_orthographic(const ShadowInputs& in, const MapFitRequest& req, ShadowSetup& setup, Trace* trace) {
    const LightBasis basis = light_basis(in.light.direction, req.up_hint);
    const std::vector<glm::dvec3> ls_points = transformed(*req.points, basis.light_from_world);
    const Aabb ls_box = bounds_of(ls_points);
    setup.maps.push_back(orthographic_map(basis.light_from_world, ls_box));
    record(trace, [&](Trace& t) {
        Step& light_space = t.add("light-space", "Light space",
                                  "rows x, y, z: z = light direction, y = up hint made perpendicular", Space::light)
                                .value("world_to_light", basis.light_from_world)
                                .value("up_hint", req.up_hint)
                                .value("up_hint_parallel_to_light", basis.up_was_degenerate ? 1.0 : 0.0)
                                .shape("points", PointSet{ls_points}, Role::focus);
        // In light space the light travels along +z: L arrives at the points' box from above.
        draw_arrow(light_space, "L", ls_box.center() - glm::dvec3(0, 0, ls_box.extent().z + ls_box.diagonal() / 4),
                   {0, 0, 1}, ls_box.diagonal() / 4, Role::light);
        t.add("light-box", "Light-space fit", "AABB of the points in light space: the orthographic projection",
              Space::light)
            .value("min", ls_box.min)
            .value("max", ls_box.max)
            .shape("fit", ls_box, Role::map);
        Step& unit = t.add("unit-cube", "Unit cube transform", "(p - min) / (max - min): the light box onto [0,1]^3",
                           Space::unit)
                         .value("light_to_unit", unit_from_box(ls_box))
                         .shape("points", PointSet{transformed(ls_points, unit_from_box(ls_box))}, Role::focus);
        draw_unit_cube(unit);
        t.set_frame(Space::light, basis.light_from_world);
    });
}

static void fit_perspective(const ShadowInputs& in, const MapFitRequest& req, ShadowSetup& setup, Trace* trace) {
    const bool spot = in.light.type == LightType::spot;
    glm::dvec3 axis = spot ? in.light.direction : req.aim - in.light.position;
    if (!(glm::length(axis) > 0.0)) axis = glm::dvec3(0, -1, 0);  // aim point at the light itself
    const double max_half_angle = spot ? in.light.cone_deg / 2 : 80.0;
    const PerspectiveFit fit = perspective_map(in.light, glm::normalize(axis), *req.points, max_half_angle);
    setup.maps.push_back(fit.map);
    if (fit.fallback) add_fallback(setup, *fit.fallback);
    record(trace, [&](Trace& t) {
        t.add("light-space", "Light view", "origin at the light, z along its axis", Space::light)
            .value("world_to_light", fit.light_from_world)
            .value("max_half_angle_deg", max_half_angle)
            .shape("points", PointSet{transformed(*req.points, fit.light_from_world)}, Role::focus)
            .shape("light", PointSet{{glm::dvec3(0.0)}}, Role::light)
            .shape("light label", Label{glm::dvec3(0.0), "light"}, Role::light);
        // The light frustum: the map's unit cube taken back into light space, its near and far planes filled.
        const glm::dmat4 uvz_from_light = fit.map.world_to_uvz * glm::inverse(fit.light_from_world);
        const Frustum light_frustum = preimage_of_box(uvz_from_light, Aabb{glm::dvec3(0.0), glm::dvec3(1.0)});
        t.add("light-frustum", "Light frustum fit",
              "tangent bounds (x/z, y/z) and distance range of the points, clamped to the cone", Space::light)
            .value("tan_min", glm::dvec2(fit.light_box.min))
            .value("tan_max", glm::dvec2(fit.light_box.max))
            .value("near", fit.light_box.min.z)
            .value("far", fit.light_box.max.z)
            .shape("light frustum", light_frustum, Role::map)
            .shape("near and far", near_and_far_faces(light_frustum), Role::map);
        t.set_frame(Space::light, fit.light_from_world);
        t.set_frame(Space::ppls, fit.map.world_to_uvz);  // a point light's own post-perspective space
    });
}

void fit_map(const ShadowInputs& inputs, const MapFitRequest& request, ShadowSetup& setup, Trace* trace) {
    if (inputs.light.is_directional())
        fit_orthographic(inputs, request, setup, trace);
    else
        fit_perspective(inputs, request, setup, trace);
}

// The result in the world: the map's own axes where world_to_uvz puts them (u and v across the
// map, d growing away from the light, each from 0 to 1) and the points it was fitted to.
void record_output(const ShadowSetup& setup, const std::vector<glm::dvec3>& covered, Trace* trace) {
    record(trace, [&](Trace& t) {
        for (size_t i = 0; i < setup.maps.size(); ++i) {
            const ShadowMap& map = setup.maps[i];
            // Appended, not prefixed: GCC 12 warns falsely of overlap (-Wrestrict) in `"x" + std::string`.
            const std::string suffix = setup.maps.size() > 1 ? std::string("-").append(std::to_string(i)) : "";
            Step& output = t.add("output" + suffix, "Map transform",
                                 "world (x,y,z,1) -> (u,v,d,w); u,v,d in [0,1] after / w", Space::world)
                               .value("world_to_uvz", map.world_to_uvz)
                               .value("z_bias_scale", map.z_bias_scale)
                               .shape("covered_points", PointSet{covered}, Role::focus);
            const ProjectionKind& kind = projection_kind(map);
            if (!kind.projective()) continue;  // its axes bend: no straight arrows
            const auto ws = [&](const glm::dvec3& uvz) { return kind.world_of(map, uvz); };
            const glm::dvec3 ws_origin = ws(glm::dvec3(0.0));
            for (const auto& [name, axis] : {std::pair{"u", glm::dvec3(1, 0, 0)}, std::pair{"v", glm::dvec3(0, 1, 0)},
                                             std::pair{"d", glm::dvec3(0, 0, 1)}})
                output.shape(name, Arrow{ws_origin, ws(axis)})
                    .shape(std::string(name) + " label", Label{ws(axis), name});
        }
        if (!setup.maps.empty()) t.set_frame(Space::unit, setup.maps.front().world_to_uvz);
    });
}

}  // namespace shadowlab
