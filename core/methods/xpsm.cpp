// Extended Perspective Shadow Maps (Gusev 2007; seed 000, section 4, steps 1 to 18), translated
// to column vectors. A projection vector P in light space's xy plane sets the warp:
// w = 1 + length(P) * (unitP · xy), chosen so that the warp depends on the distance to the viewer
// only (lengthP = coef / cos γ) and clipped so that no caster or receiver reaches w = εW.
#include "methods/xpsm.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/convex_polyhedron.hpp"
#include "math/matrix.hpp"
#include "methods/light_fit.hpp"
#include "methods/map_fit.hpp"
#include "methods/focused.hpp"
#include "methods/step_figures.hpp"
#include "methods/warp_common.hpp"

namespace shadowlab {
namespace {

// Light-space points of the casters and the receivers (steps 1 and 4).
struct LightSpacePoints {
    std::vector<glm::dvec3> casters, receivers;
};

// An interval of positions along unitP.
struct Interval {
    double min = INFINITY, max = -INFINITY;
};

// Step 4: where points fall along unitP in light space's xy plane.
Interval projection_interval(const std::vector<glm::dvec3>& ls_points, const glm::dvec2& unit_p) {
    Interval range;
    for (const glm::dvec3& p : ls_points) {
        range.min = std::min(range.min, p.x * unit_p.x + p.y * unit_p.y);
        range.max = std::max(range.max, p.x * unit_p.x + p.y * unit_p.y);
    }
    return range;
}

// The paper's Fig. 5: light space seen from the light (top-down), positions along unitP and across
// it, drawn at the height of the points nearest the light so that nothing hides the plot.
struct TopDownPlot {
    glm::dvec2 along, across;  // unitP, and unitP turned a quarter
    Interval width;            // the points' extent across unitP
    double z_min, z_max;       // the points' extent along the light
    double arm;                // a length for the arrows: a quarter of the points' xy extent

    glm::dvec3 at(double a, double c) const { return glm::dvec3(a * along + c * across, z_min); }
    // The line p.xy · unitP = a across the points.
    SegmentSet line_at(double a) const { return SegmentSet{{{at(a, width.min), at(a, width.max)}}}; }
    // An interval along unitP, drawn `c` across.
    SegmentSet interval(const Interval& i, double c) const { return SegmentSet{{{at(i.min, c), at(i.max, c)}}}; }
};

TopDownPlot top_down_plot(const LightSpacePoints& ls, const glm::dvec2& unit_p) {
    TopDownPlot plot{unit_p, {-unit_p.y, unit_p.x}, {}, INFINITY, -INFINITY, 0.0};
    Aabb bounds;
    for (const auto* points : {&ls.casters, &ls.receivers})
        for (const glm::dvec3& p : *points) {
            bounds.extend(p);
            plot.width.min = std::min(plot.width.min, glm::dot(glm::dvec2(p), plot.across));
            plot.width.max = std::max(plot.width.max, glm::dot(glm::dvec2(p), plot.across));
        }
    plot.z_min = bounds.min.z;
    plot.z_max = bounds.max.z;
    plot.arm = glm::length(glm::dvec2(bounds.extent())) / 4;
    return plot;
}

// A box's xy rectangle at height z, as its four edges: how Fig. 5 draws a PPLS box seen from the light.
SegmentSet rectangle_outline(const Aabb& box, double z) {
    const glm::dvec3 a{box.min.x, box.min.y, z}, b{box.max.x, box.min.y, z}, c{box.max.x, box.max.y, z},
        d{box.min.x, box.max.y, z};
    return SegmentSet{{{a, b}, {b, c}, {c, d}, {d, a}}};
}

// The eye (light space's origin) and the view vector V from it.
Step& draw_eye_and_view(Step& step, const glm::dvec3& ls_view, double arm) {
    step.shape("eye", PointSet{{glm::dvec3(0.0)}}, Role::view)
        .shape("eye label", Label{glm::dvec3(0.0), "eye"}, Role::view);
    return draw_arrow(step, "V", glm::dvec3(0.0), ls_view, arm, Role::view);
}

struct Warp {
    glm::dvec2 unit_p;
    double length_p;
    double min_focus_proj;  // max(minCastersProj, minReceiversProj): where the focus interval starts
};

// Steps 4 to 7: the projection vector's length, clipped away from the singularity at w = 0.
Warp projection_vector(const glm::dvec3& ls_view, const LightSpacePoints& ls, const Settings& s, Trace* trace) {
    const glm::dvec2 unit_p = glm::normalize(glm::dvec2(ls_view));
    const double cos_gamma = glm::length(glm::dvec2(ls_view));
    const double coef = s.number("coef"), epsilon_w = s.number("epsilonW");
    const Interval casters = projection_interval(ls.casters, unit_p);      // step 4
    const Interval receivers = projection_interval(ls.receivers, unit_p);  // step 4
    const double min_casters = casters.min, min_receivers = receivers.min;
    const double max_length_p = (epsilon_w - 1.0) / std::max(min_casters, min_receivers);  // step 5
    const double optimal = coef / cos_gamma;                                               // step 6
    const bool clipped = max_length_p > 0.0 && optimal > max_length_p;                     // step 7
    const Warp warp{unit_p, clipped ? max_length_p : optimal, std::max(min_casters, min_receivers)};
    record(trace, [&](Trace& t) {
        const TopDownPlot plot = top_down_plot(ls, unit_p);
        // Fig. 5: the casters' and the receivers' intervals side by side, the focus interval between.
        const double gap = 0.03 * (std::max(casters.max, receivers.max) - std::min(casters.min, receivers.min));
        const Interval focus{warp.min_focus_proj, std::min(casters.max, receivers.max)};
        Step& intervals =
            t.add("xpsm-4", "minCastersProj, minReceiversProj", "min over light-space points of p.xy · unitP",
                  Space::light)
                .value("minCastersProj", min_casters)
                .value("minReceiversProj", min_receivers)
                .shape("casters' interval", plot.interval(casters, gap), Role::casters)
                .shape("casters' label",
                       Label{plot.at(casters.min, gap), "minCastersProj = " + label_number(casters.min)}, Role::casters)
                .shape("receivers' interval", plot.interval(receivers, -gap), Role::receivers)
                .shape("receivers' label",
                       Label{plot.at(receivers.min, -gap), "minReceiversProj = " + label_number(receivers.min)},
                       Role::receivers);
        if (focus.min < focus.max) intervals.shape("focus interval", plot.interval(focus, 0.0), Role::focus);
        draw_arrow(intervals, "unitP", plot.at(std::min(casters.min, receivers.min), 2 * gap), {unit_p, 0.0}, plot.arm,
                   Role::step);
        t.add("xpsm-5", "maxLengthP", "(εW - 1) / max(minCastersProj, minReceiversProj)", Space::light)
            .value("maxLengthP", max_length_p)
            .value("epsilonW", epsilon_w)
            .shape("focus start", plot.line_at(warp.min_focus_proj), Role::focus)
            .shape("focus start label",
                   Label{plot.at(warp.min_focus_proj, plot.width.max),
                         "focus starts: w = εW here if lengthP = maxLengthP = " + label_number(max_length_p)},
                   Role::focus);
        Step& length =
            t.add("xpsm-6", "cos γ and lengthP", "cos γ = V.xy · unitP; lengthP = coef / cos γ", Space::light)
                .value("cos_gamma", cos_gamma)
                .value("coef", coef)
                .value("lengthP", optimal)
                .shape("lengthP label",
                       Label{glm::dvec3(0.0, 0.0, -plot.arm / 2), "lengthP = coef / cos γ = " + label_number(optimal)});
        draw_eye_and_view(length, ls_view, plot.arm);
        draw_arrow(length, "unitP", glm::dvec3(0.0), {unit_p, 0.0}, plot.arm, Role::step);
        draw_angle(length, "γ", glm::dvec3(0.0), ls_view, {unit_p, 0.0}, plot.arm / 2);
        // w = 1 + lengthP (p.xy · unitP) is 0 at p.xy · unitP = -1 / lengthP: the singularity.
        const double w_zero = -1.0 / warp.length_p;
        t.add("xpsm-7", "Clip lengthP", "if maxLengthP > 0 and lengthP > maxLengthP: lengthP = maxLengthP",
              Space::light)
            .value("clipped", clipped ? 1.0 : 0.0)
            .value("lengthP", warp.length_p)
            .shape("w = 0", plot.line_at(w_zero))
            .shape("w = 0 label",
                   Label{plot.at(w_zero, plot.width.max),
                         "w = 0 at lengthP = " + label_number(warp.length_p) + (clipped ? " (clipped)" : "")})
            .shape("focus start", plot.line_at(warp.min_focus_proj), Role::focus)
            .shape("focus start label",
                   Label{plot.at(warp.min_focus_proj, plot.width.min),
                         "w = " + label_number(1.0 + warp.length_p * warp.min_focus_proj)},
                   Role::focus);
    });
    return warp;
}

// Steps 8 to 10: PPLS Transform, light space -> PPLS (step 10 is recorded with the body it carries).
glm::dmat4 ppls_transform(const Warp& w, const LightSpacePoints& ls, Trace* trace) {
    const glm::dvec2 p = w.unit_p;
    const glm::dmat4 projection =
        from_rows({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {p.x * w.length_p, p.y * w.length_p, 0, 1});
    const glm::dmat4 z_rotation = from_rows({p.x, p.y, 0, 0}, {p.y, -p.x, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1});
    const glm::dmat4 ppls_from_light = z_rotation * projection;  // row-vector "Projection * ZRotation"
    record(trace, [&](Trace& t) {
        const TopDownPlot plot = top_down_plot(ls, p);
        const double w_zero = -1.0 / w.length_p;  // the plane the projection sends to infinity
        const PolygonSet singular_plane =
            PolygonSet{}.add({{plot.at(w_zero, plot.width.min), 1.0},
                              {plot.at(w_zero, plot.width.max), 1.0},
                              {plot.at(w_zero, plot.width.max) + glm::dvec3(0, 0, plot.z_max - plot.z_min), 1.0},
                              {plot.at(w_zero, plot.width.min) + glm::dvec3(0, 0, plot.z_max - plot.z_min), 1.0}});
        t.add("xpsm-8", "Projection", "w = 1 + lengthP (unitP · xy): the projection vector as the w row", Space::light)
            .value("Projection", projection)
            .shape("w = 0 plane", singular_plane)
            .shape("w = 0 label", Label{plot.at(w_zero, 0.5 * (plot.width.min + plot.width.max)), "w = 0"});
        Step& rotation = t.add("xpsm-9", "ZRotation", "rotation about z taking unitP onto the x axis", Space::light)
                             .value("ZRotation", z_rotation);
        draw_arrow(rotation, "x' = unitP", glm::dvec3(0.0), {p, 0.0}, plot.arm, Role::step);
        draw_arrow(rotation, "y'", glm::dvec3(0.0), glm::dvec3(row(z_rotation, 1)), plot.arm, Role::step);
    });
    return ppls_from_light;
}

// Where the focus interval starts (seed 3.3: below max(minCastersProj, minReceiversProj) on unitP
// no receiver has a caster above it, nor a caster a receiver below it), as a world plane whose
// kept side is p.xy · unitP >= minFocusRegionProj; there w >= εW.
Plane focus_start(const glm::dmat4& light_from_world, const Warp& warp) {
    const glm::dvec4 along = warp.unit_p.x * row(light_from_world, 0) + warp.unit_p.y * row(light_from_world, 1);
    const double length = glm::length(glm::dvec3(along));
    return {-glm::dvec3(along) / length, (warp.min_focus_proj - along.w) / length};
}

double tolerance_for(const Aabb& box) { return 1e-12 * (1.0 + box.diagonal()); }

// Step 11 for boxes (corners_within gives 8 world corners per box): each box is cut where the
// focus interval starts and what stays is projected. Leaving out single corners instead (w < εW)
// would shrink a box that crosses that line to its far corners, and the focus region could miss
// receivers a caster shadows.
ProjectedPoints project_boxes(const std::vector<glm::dvec3>& ws_corners, const Plane& start,
                              const glm::dmat4& ppls_from_world, double min_w) {
    ProjectedPoints out;
    out.points.reserve(ws_corners.size());
    auto add = [&](const glm::dvec3& p, bool keep) {
        const glm::dvec4 h = ppls_from_world * glm::dvec4(p, 1.0);
        if (h.w < min_w)
            ++out.left_out;  // counted for the trace, as the seed leaves such points out
        else if (keep)
            out.points.push_back(glm::dvec3(h) / h.w);
    };
    for (size_t i = 0; i + 8 <= ws_corners.size(); i += 8) {
        const glm::dvec3* box = &ws_corners[i];
        double lo = INFINITY, hi = -INFINITY;
        for (int k = 0; k < 8; ++k)
            lo = std::min(lo, start.signed_distance(box[k])), hi = std::max(hi, start.signed_distance(box[k]));
        const bool crosses = lo <= 0.0 && hi > 0.0;  // only these boxes are cut
        const ConvexPolyhedron kept = crosses ? clip(ConvexPolyhedron::box(bounds_of({box, box + 8})), start,
                                                     tolerance_for(bounds_of({box, box + 8})))
                                              : ConvexPolyhedron{};
        for (int k = 0; k < 8; ++k) add(box[k], hi <= 0.0 || (crosses && kept.empty()));  // a flat box stays corners
        for (const glm::dvec3& p : kept.vertices) add(p, true);
    }
    return out;
}

// The receivers' PPLS box, kept within the visible region's: receiver boxes reach behind the
// viewer, where PPLS stretches toward w = εW, but only what the camera sees needs the map.
Aabb visible_receivers_box(const Aabb& ppls_receivers_box, const ConvexPolyhedron& visible, const Plane& start,
                           const glm::dmat4& ppls_from_world, double min_w) {
    const ConvexPolyhedron seen = clip(visible, start, tolerance_for(visible.bounds()));
    if (seen.empty()) return ppls_receivers_box;
    const Aabb ppls_seen_box = bounds_of(project(seen.vertices, ppls_from_world, min_w).points);
    return {glm::max(ppls_receivers_box.min, ppls_seen_box.min), glm::min(ppls_receivers_box.max, ppls_seen_box.max)};
}

}  // namespace

ShadowSetup compute_xpsm(const ShadowInputs& in, const Settings& s, Trace* trace) {
    ShadowSetup setup;
    const auto body = start_perspective_warp("xpsm", in, s, setup, trace);
    if (!body) return setup;
    const std::vector<glm::dvec3> ws_receivers = corners_within(in.receivers, body->visible.bounds());
    const std::vector<glm::dvec3> ws_casters = corners_within(in.casters, body->body.bounds());
    if (ws_receivers.empty() || ws_casters.empty()) {
        fall_back_to_focused(Note{NoteKind::nothing_to_warp, "nothing to warp; focused map used"}, in, *body, setup,
                             trace);
        return setup;
    }

    // Step 1: LightSpace, origin at the viewer, z along the light.
    const glm::dmat4 light_from_world =
        light_basis(in.light.direction, stable_up_hint(in.light.direction), in.camera.position).light_from_world;
    const LightSpacePoints ls{transformed(ws_casters, light_from_world), transformed(ws_receivers, light_from_world)};
    // Step 2: the view vector in light space. Step 3: its xy direction.
    const glm::dvec3 v = glm::dmat3(light_from_world) * in.camera.view_direction();
    const double v_xy = glm::length(glm::dvec2(v));
    record(trace, [&](Trace& t) {
        const double arm = glm::length(glm::dvec2(bounds_of(ls.receivers).extent())) / 4;
        Step& space = t.add("xpsm-1", "LightSpace",
                            "look-at along the light from the viewer: the light travels along +z", Space::light)
                          .value("LightSpace", light_from_world)
                          .shape("Casters", PointSet{ls.casters}, Role::casters)
                          .shape("Receivers", PointSet{ls.receivers}, Role::receivers);
        draw_arrow(space, "L", glm::dvec3(0.0, 0.0, -arm), {0, 0, 1}, arm, Role::light);
        t.set_frame(Space::light, light_from_world);
        draw_eye_and_view(t.add("xpsm-2", "V", "the view vector in light space", Space::light).value("V", v), v, arm);
        Step& direction =
            t.add("xpsm-3", "unitP", "V.xy / |V.xy|; |V.xy| < 0.1 is the miner's lamp case", Space::light)
                .value("abs_V_xy", v_xy)
                .value("unitP", v_xy > 0 ? glm::dvec2(v) / v_xy : glm::dvec2(0.0))
                .shape("|V.xy| label", Label{glm::dvec3(0.0, 0.0, -arm / 2), "|V.xy| = " + label_number(v_xy)});
        draw_eye_and_view(direction, v, arm);
        if (v_xy > 0)
            draw_arrow(direction, "unitP", glm::dvec3(0.0), glm::dvec3(glm::dvec2(v) / v_xy, 0.0), arm, Role::step);
    });
    if (v_xy < 0.1) {
        fall_back_to_focused(
            Note{NoteKind::miners_lamp, "|V.xy| = " + std::to_string(v_xy) +
                                            " < 0.1, the light is almost parallel to the view; focused map used"},
            in, *body, setup, trace);
        return setup;
    }
    const Warp warp = projection_vector(v, ls, s, trace);
    const glm::dmat4 ppls_from_light = ppls_transform(warp, ls, trace);  // steps 8 to 10: PPLS Transform
    const double min_w = s.number("epsilonW") * (1.0 - 1e-9);            // the extreme point itself stays in
    record(trace, [&](Trace& t) {
        const ProjectedPoints ppls_body = project(body->body.vertices, ppls_from_light * light_from_world, min_w);
        Step& transform =
            t.add("xpsm-10", "PPLS Transform", "Projection * ZRotation (row vectors): light space -> PPLS", Space::ppls)
                .value("PPLS_Transform", ppls_from_light)
                .shape("eye", PointSet{{glm::dvec3(0.0)}}, Role::view)
                .shape("eye label", Label{glm::dvec3(0.0), "eye"}, Role::view);
        if (!ppls_body.points.empty()) transform.shape("B in PPLS", PointSet{ppls_body.points}, Role::focus);
        t.set_frame(Space::ppls, ppls_from_light * light_from_world);
    });

    // Steps 11 and 12: PPLS points (boxes cut at w = εW) and their boxes.
    const Plane start = focus_start(light_from_world, warp);
    const ProjectedPoints ppls_casters = project_boxes(ws_casters, start, ppls_from_light * light_from_world, min_w);
    const ProjectedPoints ppls_receivers =
        project_boxes(ws_receivers, start, ppls_from_light * light_from_world, min_w);
    const Aabb ppls_casters_box = bounds_of(ppls_casters.points);
    const Aabb ppls_receivers_box = visible_receivers_box(bounds_of(ppls_receivers.points), body->visible, start,
                                                          ppls_from_light * light_from_world, min_w);
    // Step 13: FocusRegion, the xy intersection of the two boxes.
    const glm::dvec2 focus_min = glm::max(glm::dvec2(ppls_casters_box.min), glm::dvec2(ppls_receivers_box.min));
    const glm::dvec2 focus_max = glm::min(glm::dvec2(ppls_casters_box.max), glm::dvec2(ppls_receivers_box.max));
    record(trace, [&](Trace& t) {
        Step& points = t.add("xpsm-11", "PPLS Casters and Receivers",
                             "points * LightSpace * PPLS Transform, boxes cut where the focus interval starts; corners "
                             "with w < εW counted as left out",
                             Space::ppls)
                           .value("casters_left_out", double(ppls_casters.left_out))
                           .value("receivers_left_out", double(ppls_receivers.left_out));
        Step& boxes = t.add("xpsm-12", "PPLS CastersBox, ReceiversBox",
                            "AABBs of the PPLS points; the receivers' kept within the visible region's", Space::ppls);
        Step& region = t.add("xpsm-13", "FocusRegion", "Intersect 2D (PPLS CastersBox, PPLS ReceiversBox)", Space::ppls)
                           .value("MinPoint", focus_min)
                           .value("MaxPoint", focus_max);
        if (ppls_casters_box.empty() || ppls_receivers_box.empty()) {  // every point of one kind left out
            for (Step* step : {&points, &boxes, &region})
                step->shape("nothing label", Label{glm::dvec3(0.0), "no PPLS point of one kind: nothing to focus on"});
            return;
        }
        points.shape("PPLS Casters", PointSet{ppls_casters.points}, Role::casters)
            .shape("PPLS Receivers", PointSet{ppls_receivers.points}, Role::receivers);
        boxes.shape("PPLS CastersBox", ppls_casters_box, Role::casters)
            .shape("PPLS ReceiversBox", ppls_receivers_box, Role::receivers);
        // Seen from the light (along z), at the top of both boxes: the two rectangles and their overlap.
        const double z = std::min(ppls_casters_box.min.z, ppls_receivers_box.min.z);
        region.shape("CastersBox", rectangle_outline(ppls_casters_box, z), Role::casters)
            .shape("ReceiversBox", rectangle_outline(ppls_receivers_box, z), Role::receivers);
        if (focus_min.x < focus_max.x && focus_min.y < focus_max.y)
            region
                .shape("FocusRegion",
                       PolygonSet{}.add({{focus_min, z, 1.0},
                                         {focus_max.x, focus_min.y, z, 1.0},
                                         {focus_max, z, 1.0},
                                         {focus_min.x, focus_max.y, z, 1.0}}),
                       Role::focus)
                .shape("FocusRegion label", Label{{focus_min, z}, "FocusRegion"}, Role::focus);
        else
            region.shape("empty label", Label{{focus_min, z}, "FocusRegion is empty"}, Role::focus);
    });
    if (ppls_casters_box.empty() || ppls_receivers_box.empty() || focus_min.x >= focus_max.x ||
        focus_min.y >= focus_max.y) {
        fall_back_to_focused(
            Note{NoteKind::empty_focus_region, "no caster's light rays meet a receiver in PPLS; focused map used"}, in,
            *body, setup, trace);
        return setup;
    }

    // Step 14: FocusRegionBasis. Step 15: its inverse, the unit cube transform.
    const double z_min = std::min(ppls_casters_box.min.z, ppls_receivers_box.min.z);
    const double z_max = std::max(ppls_casters_box.max.z, ppls_receivers_box.max.z);
    const Aabb focus{{focus_min, z_min}, {focus_max, z_max}};
    const glm::dmat4 ppls_from_uvz =
        from_rows({focus.extent().x, 0, 0, focus.min.x},  // step 14: FocusRegionBasis
                  {0, focus.extent().y, 0, focus.min.y}, {0, 0, focus.extent().z, focus.min.z}, {0, 0, 0, 1});
    const glm::dmat4 uvz_from_ppls = unit_from_box(focus);  // step 15: UnitCubeTransform
    // Steps 16 and 17: our maps stay in [0,1]^3, so NormalizedSpace is the identity.
    ShadowMap map;
    map.world_to_uvz = uvz_from_ppls * ppls_from_light * light_from_world;  // step 17: XPSM Transform
    // Step 18: bias / (MaxZ - MinZ), with the extent step 15 divides by: a flat focus region (the eye
    // at the height of a flat ground under an overhead light) has MaxZ = MinZ, widened there.
    map.z_bias_scale = uvz_from_ppls[2][2];
    setup.maps.push_back(map);
    record(trace, [&](Trace& t) {
        // The basis itself: the origin Min and the three axes scaled by (Max - Min), around the focus box.
        Step& basis = t.add("xpsm-14", "FocusRegionBasis",
                            "scale (Max - Min) and offset Min, with ZMin/ZMax of both boxes", Space::ppls)
                          .value("ZMin", z_min)
                          .value("ZMax", z_max)
                          .value("FocusRegionBasis", ppls_from_uvz)
                          .shape("focus region", focus, Role::focus)
                          .shape("Min", Label{focus.min, "Min"});
        for (int axis = 0; axis < 3; ++axis)
            basis.shape(
                std::string("axis ") + "xyz" [axis], Arrow { focus.min, focus.min + glm::dvec3(ppls_from_uvz[axis]) });
        draw_unit_cube(t.add("xpsm-15", "UnitCubeTransform",
                             "FocusRegionBasis^-1: (p - Min) / (Max - Min) (Gusev's printed step 15 has wrong signs; "
                             "his section 3.8 is right)",
                             Space::unit)
                           .value("UnitCubeTransform", uvz_from_ppls));
        // What an engine would map to here instead, drawn beside the cube it leaves unchanged.
        draw_unit_cube(t.add("xpsm-16", "NormalizedSpace",
                             "identity: maps stay in [0,1]^3 (D3D/OpenGL NDC would follow here)", Space::unit)
                           .value("NormalizedSpace", glm::dmat4(1.0))
                           .shape("OpenGL NDC", Aabb{glm::dvec3(-1.0), glm::dvec3(1.0)})
                           .shape("OpenGL NDC label", Label{{-1.0, -1.0, -1.0}, "OpenGL NDC [-1,1]³: not used here"}));
        // The composite in one figure: the world region the map covers, the unit cube taken back.
        t.add("xpsm-17", "XPSM Transform", "LightSpace, PPLS Transform, UnitCubeTransform, NormalizedSpace",
              Space::world)
            .value("XPSM_Transform", map.world_to_uvz)
            .shape("map volume", map_volume(map), Role::map);
        // The depth range the bias is divided by: MaxZ - MinZ as step 15 widens it for a flat region.
        const glm::dvec3 deepest{focus.max.x, focus.max.y, z_min};
        draw_dimension(t.add("xpsm-18", "Z bias", "Z' = (Z - bias / (MaxZ - MinZ)) / W", Space::ppls)
                           .value("z_bias_scale", map.z_bias_scale)
                           .shape("focus region", focus, Role::focus),
                       "MaxZ - MinZ", deepest, deepest + glm::dvec3(0, 0, 1.0 / map.z_bias_scale));
    });
    record_output(setup, ws_receivers, trace);
    return setup;
}

std::vector<SettingSpec> xpsm_settings() {
    return {{"coef", "warp strength: lengthP = coef / cos γ (1 / world units)", "0.05", 1e-6, 100.0, {}, -1},
            {"epsilonW", "how close to w = 0 the warp may push a caster or receiver", "0.085", 1e-3, 0.999, {}},
            body_kernel_setting()};
}

}  // namespace shadowlab
