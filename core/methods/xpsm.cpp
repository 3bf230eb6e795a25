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
#include "methods/warp_common.hpp"
#include "methods/xpsm_trace.hpp"

namespace shadowlab {
namespace {

using xpsm::Interval;
using xpsm::LightSpacePoints;
using xpsm::Warp;

// Step 4: where points fall along unitP in light space's xy plane.
Interval projection_interval(const std::vector<glm::dvec3>& ls_points, const glm::dvec2& unit_p) {
    Interval range;
    for (const glm::dvec3& p : ls_points) {
        range.min = std::min(range.min, p.x * unit_p.x + p.y * unit_p.y);
        range.max = std::max(range.max, p.x * unit_p.x + p.y * unit_p.y);
    }
    return range;
}

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
    const Warp warp{.unit_p = unit_p,
                    .length_p = clipped ? max_length_p : optimal,
                    .min_focus_proj = std::max(min_casters, min_receivers),
                    .casters = casters,
                    .receivers = receivers,
                    .cos_gamma = cos_gamma,
                    .coef = coef,
                    .epsilon_w = epsilon_w,
                    .max_length_p = max_length_p,
                    .optimal_length_p = optimal,
                    .clipped = clipped};
    xpsm::record_projection_vector(trace, warp, ls, ls_view);
    return warp;
}

// Steps 8 to 10: PPLS Transform, light space -> PPLS (step 10 is recorded with the body it carries).
glm::dmat4 ppls_transform(const Warp& w, const LightSpacePoints& ls, Trace* trace) {
    const glm::dvec2 p = w.unit_p;
    const glm::dmat4 projection =
        from_rows({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {p.x * w.length_p, p.y * w.length_p, 0, 1});
    const glm::dmat4 z_rotation = from_rows({p.x, p.y, 0, 0}, {p.y, -p.x, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1});
    const glm::dmat4 ppls_from_light = z_rotation * projection;  // row-vector "Projection * ZRotation"
    xpsm::record_ppls_factors(trace, w, ls, projection, z_rotation);
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
    xpsm::record_light_space(trace, light_from_world, ls, v);
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
    xpsm::record_ppls_transform(trace, ppls_from_light, light_from_world, body->body.vertices, min_w);

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
    xpsm::record_focus_region(trace, ppls_casters, ppls_receivers, ppls_casters_box, ppls_receivers_box, focus_min,
                              focus_max);
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
    xpsm::record_unit_cube(trace, focus, ppls_from_uvz, uvz_from_ppls, map);
    record_output(setup, ws_receivers, trace);
    return setup;
}

std::vector<SettingSpec> xpsm_settings() {
    return {{"coef", "warp strength: lengthP = coef / cos γ (1 / world units)", "0.05", 1e-6, 100.0, {}, -1},
            {"epsilonW", "how close to w = 0 the warp may push a caster or receiver", "0.085", 1e-3, 0.999, {}},
            body_kernel_setting()};
}

}  // namespace shadowlab
