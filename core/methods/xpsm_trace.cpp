#include "methods/xpsm_trace.hpp"

#include <algorithm>
#include <string>

#include "maps/map_lookup.hpp"
#include "math/matrix.hpp"
#include "methods/light_fit.hpp"
#include "methods/step_figures.hpp"

namespace shadowlab::xpsm {
namespace {

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

}  // namespace

void record_light_space(Trace* trace, const glm::dmat4& light_from_world, const LightSpacePoints& ls,
                        const glm::dvec3& v) {
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
}

void record_projection_vector(Trace* trace, const Warp& warp, const LightSpacePoints& ls, const glm::dvec3& ls_view) {
    const glm::dvec2 unit_p = warp.unit_p;
    const Interval &casters = warp.casters, &receivers = warp.receivers;
    const double min_casters = casters.min, min_receivers = receivers.min;
    const double max_length_p = warp.max_length_p, optimal = warp.optimal_length_p, cos_gamma = warp.cos_gamma;
    const double coef = warp.coef, epsilon_w = warp.epsilon_w;
    const bool clipped = warp.clipped;
    record(trace, [&](Trace& t) {
        const TopDownPlot plot = top_down_plot(ls, warp.unit_p);
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
}

void record_ppls_factors(Trace* trace, const Warp& w, const LightSpacePoints& ls, const glm::dmat4& projection,
                         const glm::dmat4& z_rotation) {
    const glm::dvec2 p = w.unit_p;
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
}

void record_ppls_transform(Trace* trace, const glm::dmat4& ppls_from_light, const glm::dmat4& light_from_world,
                           const std::vector<glm::dvec3>& ws_body, double min_w) {
    record(trace, [&](Trace& t) {
        const ProjectedPoints ppls_body = project(ws_body, ppls_from_light * light_from_world, min_w);
        Step& transform =
            t.add("xpsm-10", "PPLS Transform", "Projection * ZRotation (row vectors): light space -> PPLS", Space::ppls)
                .value("PPLS_Transform", ppls_from_light)
                .shape("eye", PointSet{{glm::dvec3(0.0)}}, Role::view)
                .shape("eye label", Label{glm::dvec3(0.0), "eye"}, Role::view);
        if (!ppls_body.points.empty()) transform.shape("B in PPLS", PointSet{ppls_body.points}, Role::focus);
        t.set_frame(Space::ppls, ppls_from_light * light_from_world);
    });
}

void record_focus_region(Trace* trace, const ProjectedPoints& ppls_casters, const ProjectedPoints& ppls_receivers,
                         const Aabb& ppls_casters_box, const Aabb& ppls_receivers_box, const glm::dvec2& focus_min,
                         const glm::dvec2& focus_max) {
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
}

void record_unit_cube(Trace* trace, const Aabb& focus, const glm::dmat4& ppls_from_uvz, const glm::dmat4& uvz_from_ppls,
                      const ShadowMap& map) {
    const double z_min = focus.min.z, z_max = focus.max.z;
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
}

}  // namespace shadowlab::xpsm
