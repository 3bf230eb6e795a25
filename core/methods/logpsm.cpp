// Logarithmic Perspective Shadow Maps (Lloyd, Govindaraju, Quammen, Molnar and Manocha, ACM TOG
// 27(4) 2008; Lloyd's 2007 UNC thesis). Section 5 bounds the perspective aliasing error over the view
// frustum and finds the parameterization that keeps it lowest, F_lp: a perspective projection (across
// the view, its s axis, texels as wide as the distance from its centre, as the eye's pixels are)
// followed by a logarithm along the view (its t axis: texel rows as deep as the view depth, where the
// perspective alone gives them the square of it). The perspective part is LiSPSM's warp in light
// space, with Lloyd's warping parameter η (lispsm_n) at 1 by default: the warp's centre at the eye's
// depth, n = z_n / sin γ, so that far / near of the warp is the eye's z_f / z_n and the log rows are the
// eye's log depths, v = log(z / z_n) / log(z_f / z_n) along the view. The map is a nonlinear kind
// (maps/log_perspective_projection): straight edges bow, and casters are split until they follow.
#include "methods/logpsm.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "maps/log_perspective_projection.hpp"
#include "math/matrix.hpp"
#include "methods/focused.hpp"
#include "methods/lispsm.hpp"
#include "methods/map_fit.hpp"
#include "methods/step_figures.hpp"
#include "methods/tessellate_setting.hpp"
#include "methods/warp_common.hpp"

namespace shadowlab {
namespace {

// Texel rows drawn by the step figures: a few, so that their spacing reads.
constexpr int kShownRows = 16;

// F_lp: the perspective warp's 4x4 for u and depth, the log of its distance for v. The warp's last
// row is the light-space distance y - C.y from its centre along the view, which runs over [n, n +
// depth(B)] on B: v covers [0, 1] there.
ShadowMap log_perspective_map(const LispsmWarp& w, double max_sagitta_texels) {
    ShadowMap map = w.map;
    map.projection = Projection::log_perspective;
    map.log_warp = {.near = w.n, .far = w.n + w.depth};
    map.max_sagitta_texels = max_sagitta_texels;
    return map;
}

double log_range(const LispsmWarp& w) { return std::log((w.n + w.depth) / w.n); }

// The light-space line across B at distance `distance` from the warp's centre, on B's face nearest the light.
std::pair<glm::dvec3, glm::dvec3> row_across(const LispsmWarp& w, double distance) {
    const double y = w.ls_centre.y + distance;
    return {{w.ls_body_box.min.x, y, w.ls_body_box.min.z}, {w.ls_body_box.max.x, y, w.ls_body_box.min.z}};
}

void record_n(Trace& t, const LispsmWarp& w, double z_n, double eta) {
    Step& step = t.add("logpsm-n", "Warping parameter n",
                       "n = (z_f - z_n) / ((z_f/z_n)^((1+η)/2) - 1) / sin γ; η = 1 (the default): n = z_n / sin γ, "
                       "the warp's centre at the eye's depth, its far / near = z_f / z_n",
                       Space::light)
                     .value("z_n", z_n)
                     .value("z_f", w.z_f)
                     .value("eta", eta)
                     .value("n", w.n);
    if (w.warps)
        draw_dimension(step, "n", w.ls_centre, w.ls_near_face);
    else
        step.shape("B box", w.ls_body_box, Role::focus)
            .shape("n label", Label{w.ls_near_face, "n = " + label_number(w.n) + ": no warp"});
}

// The map's texel rows in light space: equal steps of v are distances n (f / n)^v from C, spaced
// logarithmically across B; beside them the perspective's own rows, equal steps of v_p.
void record_rows(Trace& t, const LispsmWarp& w, const ShadowMap& map) {
    SegmentSet log_rows, perspective_rows;
    for (int k = 0; k <= kShownRows; ++k) {
        const double v = double(k) / kShownRows;
        log_rows.segments.push_back(row_across(w, log_warp_w(map.log_warp, v)));
        // v_p = f (y - n) / ((f - n) y): y = n f / (f - v_p (f - n))
        const double f = map.log_warp.far, n = map.log_warp.near;
        perspective_rows.segments.push_back(row_across(w, n * f / (f - v * (f - n))));
    }
    t.add("logpsm-rows", "Texel rows in light space",
          "row v at distance n (f/n)^v from C: as deep as the view depth (the perspective alone: as its square)",
          Space::light)
        .value("near", map.log_warp.near)
        .value("far", map.log_warp.far)
        .shape("log rows", log_rows, Role::map)
        .shape("perspective rows", perspective_rows, Role::step)
        .shape("B box", w.ls_body_box, Role::focus);
}

// The log warp in the perspective's post-perspective space (PPLS), where the perspective's own rows
// are even: v = c0 log(c1 v_p + c2) (F_lp as a log of the perspective's own v_p) with c0 = 1 / log(n / f), c1 = n / f -
// 1, c2 = 1, v_p the perspective's unit v. The map's rows, v = k / K, lie at v_p = (1 - (n / f)^v) / (1 - n / f):
// sparser than the perspective's at the near end, bunched toward far, where the perspective alone
// spends too few; the perspective's even rows beside them over half the width.
void record_log_warp(Trace& t, const LispsmWarp& w, const ShadowMap& map) {
    const double ratio = map.log_warp.near / map.log_warp.far;
    const glm::dmat4 ppls_from_uvz = glm::inverse(w.uvz_from_ppls);
    const auto row = [&](double v_p, double u_end) {
        return std::pair{transform_point(ppls_from_uvz, {0.0, v_p, 0.0}),
                         transform_point(ppls_from_uvz, {u_end, v_p, 0.0})};
    };
    SegmentSet map_rows, perspective_rows;
    for (int k = 0; k <= kShownRows; ++k) {
        const double v = double(k) / kShownRows;
        map_rows.segments.push_back(row((1.0 - std::pow(ratio, v)) / (1.0 - ratio), 1.0));
        perspective_rows.segments.push_back(row(v, 0.5));
    }
    t.add("logpsm-log", "Logarithmic warp",
          "v = c0 log(c1 v_p + c2) = log(w/n) / log(f/n): the map's rows (v = k/K) in the warped box, sparse "
          "near and bunched toward far; the perspective's even rows v_p = k/K over half the width",
          Space::ppls)
        .value("c0", 1.0 / std::log(ratio))
        .value("c1", ratio - 1.0)
        .value("c2", 1.0)
        .value("log_range", log_range(w))
        .shape("map rows", map_rows, Role::map)
        .shape("perspective rows", perspective_rows, Role::step)
        .shape("warped B", PointSet{w.ppls_body.points}, Role::focus)
        .shape("warped box", w.ppls_box, Role::map);
}

}  // namespace

ShadowSetup compute_logpsm(const ShadowInputs& in, const Settings& s, Trace* trace) {
    ShadowSetup setup;
    const auto body = start_perspective_warp("logpsm", in, s, setup, trace);
    if (!body) return setup;
    const double eta = s.number("eta"), z_n = seen_receiver_depths(in, *body).near;
    const LispsmWarp w = lispsm_warp({.ws_body = &body->body.vertices,
                                      .eye = in.camera.position,
                                      .view_direction = in.camera.view_direction(),
                                      .light_direction = in.light.direction,
                                      .z_n = z_n,
                                      .eta = eta});
    record(trace, [&](Trace& t) {
        record_light_space(t, w, glm::dmat4(1.0), in.camera.view_direction(), in.light.direction, "V");
        record_n(t, w, z_n, eta);
    });
    if (!w.warps) {
        if (eta > -1.0)
            add_fallback(setup,
                         Note{NoteKind::parallel_light, "sin γ = " + std::to_string(w.sin_gamma) +
                                                            ": the warp has faded to nothing; focused map used"});
        fit_focused(in, *body, setup, trace);
        return setup;
    }
    const bool logarithmic = log_range(w) >= kMinLogRange;
    if (!logarithmic)
        add_fallback(setup, Note{NoteKind::log_range_short,
                                 "log(far / near) = " + std::to_string(log_range(w)) + ": the perspective warp alone"});
    setup.maps.push_back(logarithmic ? log_perspective_map(w, s.number("tessellate")) : w.map);
    record(trace, [&](Trace& t) {
        record_warp(t, w, glm::dmat4(1.0));
        if (!logarithmic) return;
        record_rows(t, w, setup.maps.front());
        record_log_warp(t, w, setup.maps.front());
    });
    record_output(setup, body->body.vertices, trace);
    return setup;
}

std::vector<SettingSpec> logpsm_settings() {
    return {{.name = "eta",
             .description = "Lloyd's η for the perspective part: 1 (the default) centres it at the eye's depth",
             .default_value = "1",
             .min = -1.0,
             .max = 1.0},
            tessellate_setting("0.5"),
            body_kernel_setting()};
}

}  // namespace shadowlab
