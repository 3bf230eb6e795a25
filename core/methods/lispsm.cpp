// Light Space Perspective Shadow Maps (Wimmer, Scherzer, Purgathofer 2004; seeds 001 and 004).
// In light space, with y along the view direction made perpendicular to the light, a perspective
// warp looks along y from a centre C at distance n before the body B. Light rays (along z) stay
// parallel under it, so the map is an orthographic fit in the warped space. A spot light is warped
// after its own perspective, as the paper proposes for point lights: in the spot's post-perspective
// space its rays are parallel, so LiSPSM runs there as for a directional light, on the body taken
// into that space, with the eye's depths read as that space's map needs them (effective_depths).
#include "methods/lispsm.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "math/matrix.hpp"
#include "methods/focused.hpp"
#include "methods/light_fit.hpp"
#include "methods/map_fit.hpp"
#include "methods/step_figures.hpp"
#include "methods/warp_common.hpp"

namespace shadowlab {

// Lloyd's far / near ratio of the warp for the eye's depth ratio z_f / z_n.
static double warp_ratio(double z_n, double z_f, double eta) { return std::pow(z_f / z_n, (1.0 + eta) / 2.0); }

double lispsm_n(double z_n, double z_f, double sin_gamma, double eta) {
    return (z_f - z_n) / (warp_ratio(z_n, z_f, eta) - 1.0) / sin_gamma;
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

// LiSPSM: the map is an orthographic fit of the box in the warped space (PPLS).
void fit_unit_cube(LispsmWarp& w) {
    w.uvz_from_ppls = unit_from_box(w.ppls_box);
    w.map.world_to_uvz = w.uvz_from_ppls * w.ppls_from_light * w.light_from_world;
    w.map.z_bias_scale = 1.0 / w.ppls_box.extent().z;
}

// The warped box's far face pushed back to hold `ws_points` (world; LiSPSM ran in the space
// `space_from_world` takes them to). The near face stays: casters before it are stored at depth 0 and
// still shadow.
void extend_far_depth(LispsmWarp& w, const std::vector<glm::dvec3>& ws_points, const glm::dmat4& space_from_world) {
    const glm::dmat4 ppls_from_world = w.ppls_from_light * w.light_from_world * space_from_world;
    for (const glm::dvec3& p : project(ws_points, ppls_from_world, 0.0).points)
        w.ppls_box.max.z = std::max(w.ppls_box.max.z, p.z);
    fit_unit_cube(w);
}

// The space LiSPSM runs in and what it needs there: the world for a directional light; for a spot light
// its post-perspective space (SPPS), where its rays are parallel.
struct LispsmSpace {
    glm::dmat4 from_world{1.0};  // the identity, or the spot's perspective
    std::vector<glm::dvec3> points;
    // The warp's centre C takes its x and z from `eye` and looks along `view_direction` made
    // perpendicular to `light_direction`.
    glm::dvec3 eye, view_direction, light_direction;
    // The eye's depths of the body's near and far faces: in the world the nearest receiver the camera
    // sees, or the virtual near plane beyond it (z_f then estimated from the body); in SPPS both, as
    // only their ratio counts there.
    double z_n, z_f = 0.0;
    DepthRange seen{};  // in the world: the receivers' view depths z_n was read from
};

// The virtual near plane (Filament's shadowNearHint): the warp's eye range starts `near_hint` of the
// way from the nearest to the farthest receiver seen, spending no texel on what lies before it. A
// fraction of that range, not Filament's absolute 1 m, so that moving or scaling the scene changes
// nothing; 0 (the default) is off, as a distance in metres would be meaningless for a model in
// millimetres or at 1,000 units.
double virtual_near(const DepthRange& seen, double near_hint) { return seen.near + near_hint * (seen.far - seen.near); }

LispsmSpace world_space(const ShadowInputs& in, const IntersectionBody& body, const std::vector<glm::dvec3>& ws_points,
                        double near_hint) {
    const DepthRange seen = seen_receiver_depths(in, body);
    return {.points = ws_points,
            .eye = in.camera.position,
            .view_direction = in.camera.view_direction(),
            .light_direction = in.light.direction,
            .z_n = virtual_near(seen, near_hint),
            .seen = seen};
}

// The spot's perspective about its axis (light space at the light, as perspective_map builds it):
// x' = x / z, y' = y / z, z' = -z_ref / z. Rays from the light become lines of constant (x', y') running
// along +z'. z_ref only scales depth (the final fit is per axis): the points' mean z gives z' a range
// like the tangents'.
glm::dmat4 spps_from_world(const Light& spot, const std::vector<glm::dvec3>& ws_points) {
    const glm::dmat4 light_from_world =
        light_basis(spot.direction, stable_up_hint(spot.direction), spot.position).light_from_world;
    double z_ref = 0.0;
    for (const glm::dvec3& p : ws_points) z_ref += transform_point(light_from_world, p).z / double(ws_points.size());
    return from_rows({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 0, -z_ref}, {0, 0, 1, 0}) * light_from_world;
}

// What LiSPSM reads off the eye, in SPPS. Unwarped, SPPS gives texels as wide as the distance z from
// the spot's plane, while pixels grow with the view depth t: the error m goes as z / t, where for a
// directional light it goes as 1 / t. So e = t / z plays the view depth's part, and LiSPSM's choices
// carry over with e for t: its y axis (the view made perpendicular to the light: where t grows across
// the map) becomes the direction in which e grows across the map, and z_n, z_f are e at the body's
// faces across it. e varies about linearly over the body: a least-squares plane e ≈ e0 + g · (x', y')
// through its values at the points gives both. The spot's own perspective often does most of the
// work (z_f / z_n near 1: a weak warp); e constant across the map (g = 0) asks for none.
struct EffectiveDepths {
    glm::dvec2 gradient{0.0};  // g, in SPPS's (x', y')
    double z_n = 0.0, z_f = 0.0;
};

EffectiveDepths effective_depths(const ShadowInputs& in, const std::vector<glm::dvec3>& ws_points,
                                 const glm::dmat4& spps_from_world) {
    std::vector<glm::dvec2> tangents;  // (x', y') of each point
    std::vector<double> es;
    glm::dvec2 mean_tangent{0.0};
    double mean_e = 0.0;
    for (const glm::dvec3& p : ws_points) {
        const glm::dvec4 h = spps_from_world * glm::dvec4(p, 1.0);  // h.w = z, the distance from the spot's plane
        const double t = std::max(glm::dot(p - in.camera.position, in.camera.view_direction()), in.camera.near);
        tangents.push_back(glm::dvec2(h) / h.w);
        es.push_back(t / h.w);
        mean_tangent += tangents.back() / double(ws_points.size());
        mean_e += es.back() / double(ws_points.size());
    }
    glm::dmat2 scatter{0.0};
    glm::dvec2 covariance{0.0};
    for (size_t i = 0; i < es.size(); ++i) {
        const glm::dvec2 d = tangents[i] - mean_tangent;
        scatter += glm::outerProduct(d, d);
        covariance += d * (es[i] - mean_e);
    }
    EffectiveDepths depths{.z_n = mean_e, .z_f = mean_e};
    if (!(std::abs(glm::determinant(scatter)) > 1e-12 * std::pow(scatter[0][0] + scatter[1][1], 2))) return depths;
    depths.gradient = glm::inverse(scatter) * covariance;
    if (!(glm::length(depths.gradient) > 0.0)) return depths;
    const glm::dvec2 across = glm::normalize(depths.gradient);
    double lowest = INFINITY, highest = -INFINITY;
    for (const glm::dvec2& tangent : tangents) {
        lowest = std::min(lowest, glm::dot(tangent - mean_tangent, across));
        highest = std::max(highest, glm::dot(tangent - mean_tangent, across));
    }
    depths.z_n = mean_e + glm::length(depths.gradient) * lowest;
    depths.z_f = mean_e + glm::length(depths.gradient) * highest;
    return depths;
}

// LiSPSM in SPPS: the light along +z', y along g, and C on the line along g through the body's
// centroid, as LiSPSM's C lies on the line of sight through the eye.
LispsmSpace spot_space(const ShadowInputs& in, const std::vector<glm::dvec3>& ws_points) {
    const glm::dmat4 to_spps = spps_from_world(in.light, ws_points);
    const EffectiveDepths depths = effective_depths(in, ws_points, to_spps);
    LispsmSpace space{.from_world = to_spps,
                      .points = project(ws_points, to_spps, 0.0).points,
                      .view_direction = glm::dvec3(depths.gradient, 0.0),
                      .light_direction = {0, 0, 1},
                      .z_n = depths.z_n,
                      .z_f = depths.z_f};
    if (!(glm::length(depths.gradient) > 0.0)) space.view_direction = {0, 1, 0};  // any axis: no warp follows
    space.eye = glm::dvec3(0.0);
    for (const glm::dvec3& p : space.points) space.eye += p / double(space.points.size());
    return space;
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
    if (req.z_f > 0.0) {  // the eye's depths given: n makes the warp's far / near, (n + depth) / n, Lloyd's ratio
        w.z_f = req.z_f;
        const double ratio = warp_ratio(req.z_n, w.z_f, req.eta);
        w.n = ratio > 1.0 ? w.depth / (ratio - 1.0) : INFINITY;  // a far end needing more texels: no warp helps
    } else {
        w.z_f = req.z_n + w.depth * w.sin_gamma;
        w.n = lispsm_n(req.z_n, w.z_f, w.sin_gamma, req.eta);
    }
    if (req.n > 0.0) w.n = req.n;
    w.warps = w.n < kNoWarp * w.depth;  // also false for n = ∞ and NaN at γ = 0
    // LiSPSM: the warp frustum's centre, n before the body's near face, at the eye's x and z.
    w.ls_eye = transform_point(w.light_from_world, req.eye);
    w.ls_near_face = {w.ls_eye.x, w.ls_body_box.min.y, w.ls_eye.z};
    w.ls_centre = w.ls_near_face - glm::dvec3(0, w.n, 0);
    if (!w.warps) return w;
    w.ppls_from_light = warp_matrix(w.ls_centre, w.n, w.n + w.depth);
    w.ppls_body = project(*req.ws_body, w.ppls_from_light * w.light_from_world, 0.0);
    w.ppls_box = bounds_of(w.ppls_body.points);
    fit_unit_cube(w);
    return w;
}

void record_light_space(Trace& t, const LispsmWarp& w, const glm::dmat4& space_from_world,
                        const glm::dvec3& view_direction, const glm::dvec3& light_direction,
                        const std::string& view_name) {
    t.add("light-space", "Light space", "z = light direction, y = view direction made perpendicular to it",
          Space::light)
        .value("world_to_light", w.light_from_world)
        .shape("B", PointSet{w.ls_body}, Role::focus)
        .shape("B box", w.ls_body_box, Role::focus);
    t.set_frame(Space::light, w.light_from_world * space_from_world);
    // γ is the angle between the view direction V and the light direction L (+z in light space).
    const glm::dvec3 ls_view = glm::dmat3(w.light_from_world) * view_direction, ls_light{0, 0, 1};
    const double arm = w.ls_body_box.diagonal() / 4;
    const double cos_gamma = glm::dot(view_direction, light_direction);
    Step& gamma =
        t.add("gamma", "Angle γ", "sin γ = |view × light|: 1 when the light is perpendicular to the view", Space::light)
            .value("sin_gamma", w.sin_gamma)
            .value("gamma_deg", glm::degrees(std::atan2(w.sin_gamma, cos_gamma)));
    draw_arrow(gamma, view_name, w.ls_eye, ls_view, arm, Role::view);
    draw_arrow(gamma, "L", w.ls_eye, ls_light, arm, Role::light);
    draw_angle(gamma, "γ", w.ls_eye, ls_view, ls_light, arm / 2);
}

void record_warp(Trace& t, const LispsmWarp& w, const glm::dmat4& space_from_world) {
    Step& frustum = t.add("warp-frustum", "Warp frustum",
                          "centre C = (eye x, near face of B - n, eye z), near n, far n + depth(B)", Space::light)
                        .value("C", w.ls_centre)
                        .value("near", w.n)
                        .value("far", w.n + w.depth);
    draw_warp_frustum(frustum, w);
    t.add("warp", "Perspective warp P", "x' = x/y, y' = f(y - n)/((f - n) y), z' = z/y about C", Space::ppls)
        .value("P", w.ppls_from_light)
        .shape("warped B", PointSet{w.ppls_body.points}, Role::focus)
        .shape("warped box", w.ppls_box, Role::map);
    t.set_frame(Space::ppls, w.ppls_from_light * w.light_from_world * space_from_world);
}

void draw_warp_frustum(Step& step, const LispsmWarp& w) {
    const Frustum warp_frustum = preimage_of_box(w.ppls_from_light, w.ppls_box, 1);
    step.shape("P", warp_frustum)
        .shape("near and far planes", near_and_far_faces(warp_frustum))
        .shape("C", PointSet{{w.ls_centre}})
        .shape("C label", Label{w.ls_centre, "C"})
        .shape("near label", Label{w.ls_near_face, "near n = " + label_number(w.n)})
        .shape("far label",
               Label{w.ls_near_face + glm::dvec3(0, w.depth, 0), "far n + depth = " + label_number(w.n + w.depth)});
}

namespace {

// The spot's perspective as LiSPSM's first step, in LiSPSM's light space of SPPS: the points to cover,
// parallel rays through them, and the direction g in which the eye's effective depth grows.
void record_light_perspective(Trace& t, const LispsmSpace& space, const LispsmWarp& w) {
    Step& step = t.add("light-perspective", "Spot's perspective",
                       "x' = x/z, y' = y/z, z' = -z_ref/z about the spot's axis: its rays become parallel; e = t/z "
                       "(view depth over light depth) grows along g",
                       Space::light)
                     .value("world_to_spps", space.from_world)
                     .value("e_near", space.z_n)
                     .value("e_far", space.z_f)
                     .shape("B'", PointSet{w.ls_body}, Role::focus);
    SegmentSet rays;  // the rays through the box's corners nearest the light, across the box along +z
    for (const glm::dvec3& c : w.ls_body_box.corners())
        if (c.z == w.ls_body_box.min.z) rays.segments.push_back({c, c + glm::dvec3(0, 0, w.ls_body_box.extent().z)});
    step.shape("parallel rays", rays, Role::light);
    draw_arrow(step, "g", w.ls_eye, glm::dmat3(w.light_from_world) * space.view_direction, w.ls_body_box.diagonal() / 4,
               Role::view);
}

}  // namespace

ShadowSetup compute_lispsm(const ShadowInputs& in, const Settings& s, Trace* trace) {
    ShadowSetup setup;
    const auto region = start_warp_in_reach("lispsm", in, s, setup, trace);
    if (!region) return setup;
    if (in.light.type == LightType::point) {
        fall_back_to_focused(Note{NoteKind::no_light_axis,
                                  "lispsm warps directional and spot lights; focused map "
                                  "used"},
                             in, region->body, setup, trace);
        return setup;
    }
    const bool spot = in.light.type == LightType::spot;
    const LispsmSpace space = spot ? spot_space(in, region->ws_points)
                                   : world_space(in, region->body, region->ws_points, s.number("near_hint"));

    const double eta = s.number("eta");
    LispsmWarp w = lispsm_warp({.ws_body = &space.points,
                                .eye = space.eye,
                                .view_direction = space.view_direction,
                                .light_direction = space.light_direction,
                                .z_n = space.z_n,
                                .eta = eta,
                                .n = s.number("n"),
                                .z_f = space.z_f});
    if (spot && w.warps)  // visible points beyond the cone that the map's square takes in: not past its far plane
        extend_far_depth(
            w, body_within_frustum(region->body.body, w.map.world_to_uvz * space.from_world, in.light.position),
            space.from_world);
    record(trace, [&](Trace& t) {
        if (spot) record_light_perspective(t, space, w);
        // In SPPS g stands for the view: γ = 90° by construction.
        record_light_space(t, w, space.from_world, space.view_direction, space.light_direction, spot ? "g" : "V");
        Step& n_opt = t.add("n-opt", "n_opt",
                            "n = (z_n + sqrt(z_n z_f)) / sin γ, z_f = z_n + depth(B) sin γ; Lloyd's η: "
                            "warp far/near = (z_f/z_n)^((1+η)/2); z_n: the nearest receiver seen (or the virtual "
                            "near plane near_hint of the way to the farthest), not the camera's near plane",
                            Space::light)
                          .value("z_n", space.z_n)
                          .value("z_f", w.z_f)
                          .value("eta", eta)
                          .value("n", w.n)
                          .value("n_overridden", s.number("n") > 0.0 ? 1.0 : 0.0);
        if (!spot)
            n_opt.value("camera_near", in.camera.near)
                .value("receivers_near", space.seen.near)
                .value("receivers_far", space.seen.far)
                .value("near_hint", s.number("near_hint"));
        if (w.warps)
            draw_dimension(n_opt, "n", w.ls_centre, w.ls_near_face);
        else
            n_opt.shape("B box", w.ls_body_box, Role::focus)
                .shape("n label", Label{w.ls_near_face, "n = " + label_number(w.n) + ": no warp"});
    });
    if (!w.warps) {
        if (eta > -1.0 && s.number("n") <= 0.0)
            add_fallback(setup, spot ? Note{NoteKind::warp_not_needed, "e = t/z from " + std::to_string(space.z_n) +
                                                                           " to " + std::to_string(space.z_f) +
                                                                           " across the map; focused map used"}
                                     : Note{NoteKind::parallel_light, "sin γ = " + std::to_string(w.sin_gamma) +
                                                                          ": the warp has faded to nothing; focused "
                                                                          "map used"});
        fit_focused(in, region->body, setup, trace);
        return setup;
    }

    ShadowMap map = w.map;
    map.world_to_uvz = w.map.world_to_uvz * space.from_world;
    if (spot) {  // the depth slope along the spot's rays varies: bias in world units exact at the visible centre
        const glm::dvec3 visible_centre = region->body.visible.centroid();
        map.z_bias_scale = depth_slope_along(map.world_to_uvz, light_ray_at(in.light, visible_centre), visible_centre);
    }
    setup.maps.push_back(map);
    record(trace, [&](Trace& t) {
        record_warp(t, w, space.from_world);
        Step& unit =
            t.add("unit-cube", "Unit cube transform", "(p - min) / (max - min) over the warped body", Space::unit)
                .value("warped_to_unit", w.uvz_from_ppls)
                .shape("warped B", PointSet{transformed(w.ppls_body.points, w.uvz_from_ppls)}, Role::focus);
        draw_unit_cube(unit);
    });
    record_output(setup, region->ws_points, trace);
    return setup;
}

std::vector<SettingSpec> lispsm_settings() {
    return {{"eta", "Lloyd's η: -1 uniform, 0 LiSPSM's n_opt, 1 PSM-like", "0", -1.0, 1.0, {}},
            {"n", "warp near distance; 0 = automatic (n_opt)", "0", 0.0, 1e12, {}, 1},
            {"near_hint",
             "virtual near plane: the eye's range starts this fraction of the way from the nearest to the farthest "
             "receiver seen (0: at the nearest)",
             "0",
             0.0,
             0.66,
             {}},
            {"depths",
             "the receivers' view depths: of their boxes within the visible region, or of the camera's depth image",
             "boxes",
             0.0,
             0.0,
             {"boxes", "image"}},
            body_kernel_setting()};
}

bool lispsm_reads_visible_depths(const Settings& s) { return s.choice("depths") == "image"; }

}  // namespace shadowlab
