// Light Space Perspective Shadow Maps (Wimmer, Scherzer, Purgathofer 2004; seeds 001 and 004).
// In light space, with y along the view direction made perpendicular to the light, a perspective
// warp looks along y from a centre C at distance n before the body B. Light rays (along z) stay
// parallel under it, so the map is an orthographic fit in the warped space.
#include "methods/lispsm.hpp"

#include <cmath>

#include "math/matrix.hpp"
#include "methods/focused.hpp"
#include "methods/light_fit.hpp"
#include "methods/map_fit.hpp"
#include "methods/step_figures.hpp"
#include "methods/warp_common.hpp"

namespace shadowlab {

double lispsm_n(double z_n, double z_f, double sin_gamma, double eta) {
    const double ratio = std::pow(z_f / z_n, (1.0 + eta) / 2.0);  // the warp's far / near
    return (z_f - z_n) / (ratio - 1.0) / sin_gamma;
}

namespace {

// A warp weaker than this (n this many times the body's depth: under 0.01% of distortion) is none.
constexpr double kNoWarp = 1e4;

// LiSPSM's warp P, light space -> PPLS: the perspective along +y from `ls_centre`: x' = x/y,
// z' = z/y, y' = f (y - n) / ((f - n) y), all relative to the centre; light rays (along z) keep
// their x', y'.
glm::dmat4 warp_matrix(const glm::dvec3& ls_centre, double n, double f) {
    const glm::dmat4 centred_from_light =
        from_rows({1, 0, 0, -ls_centre.x}, {0, 1, 0, -ls_centre.y}, {0, 0, 1, -ls_centre.z}, {0, 0, 0, 1});
    const glm::dmat4 ppls_from_centred =
        from_rows({1, 0, 0, 0}, {0, f / (f - n), 0, -f * n / (f - n)}, {0, 0, 1, 0}, {0, 1, 0, 0});
    return ppls_from_centred * centred_from_light;
}

}  // namespace

ShadowSetup compute_lispsm(const ShadowInputs& in, const Settings& s, Trace* trace) {
    ShadowSetup setup;
    const auto body = start_warp("lispsm", in, s, setup, trace);
    if (!body) return setup;

    // LiSPSM: light space with y along the view direction made perpendicular to the light.
    const glm::dvec3 view_dir = in.camera.view_direction();
    const double sin_gamma = glm::length(glm::cross(view_dir, in.light.direction));
    const glm::dmat4 light_from_world = light_basis(in.light.direction, view_dir).light_from_world;
    const std::vector<glm::dvec3> ls_body = transformed(body->body.vertices, light_from_world);
    const Aabb ls_body_box = bounds_of(ls_body);
    // LiSPSM: n_opt from the eye's near plane and the body's depth seen along the view (Wimmer's z_f).
    const double z_n = in.camera.near;
    const double depth = ls_body_box.extent().y;
    const double z_f = z_n + depth * sin_gamma;
    const double eta = s.number("eta");
    const double n = s.number("n") > 0.0 ? s.number("n") : lispsm_n(z_n, z_f, sin_gamma, eta);
    const bool warps = n < kNoWarp * depth;  // also false for n = ∞ and NaN at γ = 0
    // LiSPSM: the warp frustum's centre, n before the body's near face, at the eye's x and z.
    const glm::dvec3 ls_eye = transform_point(light_from_world, in.camera.position);
    const glm::dvec3 ls_near_face{ls_eye.x, ls_body_box.min.y, ls_eye.z};
    const glm::dvec3 ls_centre = ls_near_face - glm::dvec3(0, n, 0);
    record(trace, [&](Trace& t) {
        t.add("light-space", "Light space", "z = light direction, y = view direction made perpendicular to it",
              Space::light)
            .value("world_to_light", light_from_world)
            .shape("B", PointSet{ls_body}, Role::focus).shape("B box", ls_body_box, Role::focus);
        t.set_frame(Space::light, light_from_world);
        // γ is the angle between the view direction V and the light direction L (+z in light space).
        const glm::dvec3 ls_view = glm::dmat3(light_from_world) * view_dir, ls_light{0, 0, 1};
        const double arm = ls_body_box.diagonal() / 4;
        Step& gamma = t.add("gamma", "Angle γ", "sin γ = |view × light|: 1 when the light is perpendicular to the view",
                            Space::light)
                          .value("sin_gamma", sin_gamma)
                          .value("gamma_deg", glm::degrees(std::atan2(sin_gamma, glm::dot(view_dir, in.light.direction))));
        draw_arrow(gamma, "V", ls_eye, ls_view, arm, Role::view);
        draw_arrow(gamma, "L", ls_eye, ls_light, arm, Role::light);
        draw_angle(gamma, "γ", ls_eye, ls_view, ls_light, arm / 2);
        Step& n_opt = t.add("n-opt", "n_opt", "n = (z_n + sqrt(z_n z_f)) / sin γ, z_f = z_n + depth(B) sin γ; Lloyd's η: "
                            "warp far/near = (z_f/z_n)^((1+η)/2)", Space::light)
                          .value("z_n", z_n).value("z_f", z_f).value("eta", eta).value("n", n)
                          .value("n_overridden", s.number("n") > 0.0 ? 1.0 : 0.0);
        if (warps) draw_dimension(n_opt, "n", ls_centre, ls_near_face);
        else n_opt.shape("B box", ls_body_box, Role::focus)
                 .shape("n label", Label{ls_near_face, "n = " + label_number(n) + ": no warp"});
    });
    if (!warps) {
        if (eta > -1.0 && s.number("n") <= 0.0)
            add_fallback(setup, Note{NoteKind::parallel_light,
                                                "sin γ = " + std::to_string(sin_gamma) +
                                                    ": the warp has faded to nothing; focused map used"});
        fit_focused(in, *body, setup, trace);
        return setup;
    }

    const glm::dmat4 ppls_from_light = warp_matrix(ls_centre, n, n + depth);
    const ProjectedPoints ppls_body = project(body->body.vertices, ppls_from_light * light_from_world, 0.0);
    const Aabb ppls_box = bounds_of(ppls_body.points);
    // LiSPSM: the map is an orthographic fit in the warped space (PPLS).
    const glm::dmat4 uvz_from_ppls = unit_from_box(ppls_box);
    ShadowMap map;
    map.world_to_uvz = uvz_from_ppls * ppls_from_light * light_from_world;
    map.z_bias_scale = 1.0 / ppls_box.extent().z;
    setup.maps.push_back(map);
    record(trace, [&](Trace& t) {
        // P itself: the warped body's box taken back into light space, looking along +y from C.
        const Frustum warp_frustum = preimage_of_box(ppls_from_light, ppls_box, 1);
        t.add("warp-frustum", "Warp frustum", "centre C = (eye x, near face of B - n, eye z), near n, far n + depth(B)",
              Space::light)
            .value("C", ls_centre).value("near", n).value("far", n + depth)
            .shape("P", warp_frustum).shape("near and far planes", near_and_far_faces(warp_frustum))
            .shape("C", PointSet{{ls_centre}}).shape("C label", Label{ls_centre, "C"})
            .shape("near label", Label{ls_near_face, "near n = " + label_number(n)})
            .shape("far label", Label{ls_near_face + glm::dvec3(0, depth, 0), "far n + depth = " + label_number(n + depth)});
        t.add("warp", "Perspective warp P", "x' = x/y, y' = f(y - n)/((f - n) y), z' = z/y about C", Space::ppls)
            .value("P", ppls_from_light)
            .shape("warped B", PointSet{ppls_body.points}, Role::focus).shape("warped box", ppls_box, Role::map);
        t.set_frame(Space::ppls, ppls_from_light * light_from_world);
        Step& unit = t.add("unit-cube", "Unit cube transform", "(p - min) / (max - min) over the warped body",
                           Space::unit)
                         .value("warped_to_unit", uvz_from_ppls)
                         .shape("warped B", PointSet{transformed(ppls_body.points, uvz_from_ppls)}, Role::focus);
        draw_unit_cube(unit);
    });
    record_output(setup, body->body.vertices, trace);
    return setup;
}

std::vector<SettingSpec> lispsm_settings() {
    return {{"eta", "Lloyd's η: -1 uniform, 0 LiSPSM's n_opt, 1 PSM-like", "0", -1.0, 1.0, {}},
            {"n", "warp near distance; 0 = automatic (n_opt)", "0", 0.0, 1e12, {}, 1},
            body_kernel_setting()};
}

}  // namespace shadowlab
