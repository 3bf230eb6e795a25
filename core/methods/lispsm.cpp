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

LispsmWarp lispsm_warp(const LispsmRequest& req) {
    LispsmWarp w;
    // LiSPSM: light space with y along the view direction made perpendicular to the light.
    w.sin_gamma = glm::length(glm::cross(req.view_direction, req.light_direction));
    w.light_from_world = light_basis(req.light_direction, req.view_direction).light_from_world;
    w.ls_body = transformed(*req.ws_body, w.light_from_world);
    w.ls_body_box = bounds_of(w.ls_body);
    // LiSPSM: n_opt from the eye's near plane and the body's depth seen along the view (Wimmer's z_f).
    w.depth = w.ls_body_box.extent().y;
    w.z_f = req.z_n + w.depth * w.sin_gamma;
    w.n = req.n > 0.0 ? req.n : lispsm_n(req.z_n, w.z_f, w.sin_gamma, req.eta);
    w.warps = w.n < kNoWarp * w.depth;  // also false for n = ∞ and NaN at γ = 0
    // LiSPSM: the warp frustum's centre, n before the body's near face, at the eye's x and z.
    w.ls_eye = transform_point(w.light_from_world, req.eye);
    w.ls_near_face = {w.ls_eye.x, w.ls_body_box.min.y, w.ls_eye.z};
    w.ls_centre = w.ls_near_face - glm::dvec3(0, w.n, 0);
    if (!w.warps) return w;
    w.ppls_from_light = warp_matrix(w.ls_centre, w.n, w.n + w.depth);
    w.ppls_body = project(*req.ws_body, w.ppls_from_light * w.light_from_world, 0.0);
    w.ppls_box = bounds_of(w.ppls_body.points);
    // LiSPSM: the map is an orthographic fit in the warped space (PPLS).
    w.uvz_from_ppls = unit_from_box(w.ppls_box);
    w.map.world_to_uvz = w.uvz_from_ppls * w.ppls_from_light * w.light_from_world;
    w.map.z_bias_scale = 1.0 / w.ppls_box.extent().z;
    return w;
}

void draw_warp_frustum(Step& step, const LispsmWarp& w) {
    const Frustum warp_frustum = preimage_of_box(w.ppls_from_light, w.ppls_box, 1);
    step.shape("P", warp_frustum).shape("near and far planes", near_and_far_faces(warp_frustum))
        .shape("C", PointSet{{w.ls_centre}}).shape("C label", Label{w.ls_centre, "C"})
        .shape("near label", Label{w.ls_near_face, "near n = " + label_number(w.n)})
        .shape("far label", Label{w.ls_near_face + glm::dvec3(0, w.depth, 0), "far n + depth = " + label_number(w.n + w.depth)});
}

ShadowSetup compute_lispsm(const ShadowInputs& in, const Settings& s, Trace* trace) {
    ShadowSetup setup;
    const auto body = start_warp("lispsm", in, s, setup, trace);
    if (!body) return setup;

    const glm::dvec3 view_dir = in.camera.view_direction();
    const double eta = s.number("eta");
    const LispsmWarp w = lispsm_warp({.ws_body = &body->body.vertices,
                                      .eye = in.camera.position,
                                      .view_direction = view_dir,
                                      .light_direction = in.light.direction,
                                      .z_n = in.camera.near,
                                      .eta = eta,
                                      .n = s.number("n")});
    record(trace, [&](Trace& t) {
        t.add("light-space", "Light space", "z = light direction, y = view direction made perpendicular to it",
              Space::light)
            .value("world_to_light", w.light_from_world)
            .shape("B", PointSet{w.ls_body}, Role::focus).shape("B box", w.ls_body_box, Role::focus);
        t.set_frame(Space::light, w.light_from_world);
        // γ is the angle between the view direction V and the light direction L (+z in light space).
        const glm::dvec3 ls_view = glm::dmat3(w.light_from_world) * view_dir, ls_light{0, 0, 1};
        const double arm = w.ls_body_box.diagonal() / 4;
        Step& gamma = t.add("gamma", "Angle γ", "sin γ = |view × light|: 1 when the light is perpendicular to the view",
                            Space::light)
                          .value("sin_gamma", w.sin_gamma)
                          .value("gamma_deg", glm::degrees(std::atan2(w.sin_gamma, glm::dot(view_dir, in.light.direction))));
        draw_arrow(gamma, "V", w.ls_eye, ls_view, arm, Role::view);
        draw_arrow(gamma, "L", w.ls_eye, ls_light, arm, Role::light);
        draw_angle(gamma, "γ", w.ls_eye, ls_view, ls_light, arm / 2);
        Step& n_opt = t.add("n-opt", "n_opt", "n = (z_n + sqrt(z_n z_f)) / sin γ, z_f = z_n + depth(B) sin γ; Lloyd's η: "
                            "warp far/near = (z_f/z_n)^((1+η)/2)", Space::light)
                          .value("z_n", in.camera.near).value("z_f", w.z_f).value("eta", eta).value("n", w.n)
                          .value("n_overridden", s.number("n") > 0.0 ? 1.0 : 0.0);
        if (w.warps) draw_dimension(n_opt, "n", w.ls_centre, w.ls_near_face);
        else n_opt.shape("B box", w.ls_body_box, Role::focus)
                 .shape("n label", Label{w.ls_near_face, "n = " + label_number(w.n) + ": no warp"});
    });
    if (!w.warps) {
        if (eta > -1.0 && s.number("n") <= 0.0)
            add_fallback(setup, Note{NoteKind::parallel_light,
                                                "sin γ = " + std::to_string(w.sin_gamma) +
                                                    ": the warp has faded to nothing; focused map used"});
        fit_focused(in, *body, setup, trace);
        return setup;
    }

    setup.maps.push_back(w.map);
    record(trace, [&](Trace& t) {
        Step& frustum = t.add("warp-frustum", "Warp frustum",
                              "centre C = (eye x, near face of B - n, eye z), near n, far n + depth(B)", Space::light)
                            .value("C", w.ls_centre).value("near", w.n).value("far", w.n + w.depth);
        draw_warp_frustum(frustum, w);
        t.add("warp", "Perspective warp P", "x' = x/y, y' = f(y - n)/((f - n) y), z' = z/y about C", Space::ppls)
            .value("P", w.ppls_from_light)
            .shape("warped B", PointSet{w.ppls_body.points}, Role::focus).shape("warped box", w.ppls_box, Role::map);
        t.set_frame(Space::ppls, w.ppls_from_light * w.light_from_world);
        Step& unit = t.add("unit-cube", "Unit cube transform", "(p - min) / (max - min) over the warped body",
                           Space::unit)
                         .value("warped_to_unit", w.uvz_from_ppls)
                         .shape("warped B", PointSet{transformed(w.ppls_body.points, w.uvz_from_ppls)}, Role::focus);
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
