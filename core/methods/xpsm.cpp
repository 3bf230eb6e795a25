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

namespace shadowlab {
namespace {

double min_projection(const std::vector<glm::dvec3>& ls_points, const glm::dvec2& unit_p) {
    double m = INFINITY;
    for (const glm::dvec3& p : ls_points) m = std::min(m, p.x * unit_p.x + p.y * unit_p.y);
    return m;
}

struct Warp {
    glm::dvec2 unit_p;
    double length_p;
    double min_focus_proj;  // max(minCastersProj, minReceiversProj): where the focus interval starts
};

// Steps 4 to 7: the projection vector's length, clipped away from the singularity at w = 0.
Warp projection_vector(const glm::dvec2& unit_p, double cos_gamma, const std::vector<glm::dvec3>& ls_casters,
                       const std::vector<glm::dvec3>& ls_receivers, const Settings& s, Trace* trace) {
    const double coef = s.number("coef"), epsilon_w = s.number("epsilonW");
    const double min_casters = min_projection(ls_casters, unit_p);      // step 4
    const double min_receivers = min_projection(ls_receivers, unit_p);  // step 4
    const double max_length_p = (epsilon_w - 1.0) / std::max(min_casters, min_receivers);  // step 5
    const double optimal = coef / cos_gamma;                                                // step 6
    const bool clipped = max_length_p > 0.0 && optimal > max_length_p;                     // step 7
    const Warp warp{unit_p, clipped ? max_length_p : optimal, std::max(min_casters, min_receivers)};
    record(trace, [&](Trace& t) {
        t.add("xpsm-4", "minCastersProj, minReceiversProj", "min over light-space points of p.xy · unitP",
              Space::light)
            .value("minCastersProj", min_casters).value("minReceiversProj", min_receivers);
        t.add("xpsm-5", "maxLengthP", "(εW - 1) / max(minCastersProj, minReceiversProj)", Space::light)
            .value("maxLengthP", max_length_p).value("epsilonW", epsilon_w);
        t.add("xpsm-6", "cos γ and lengthP", "cos γ = V.xy · unitP; lengthP = coef / cos γ", Space::light)
            .value("cos_gamma", cos_gamma).value("coef", coef).value("lengthP", optimal);
        t.add("xpsm-7", "Clip lengthP", "if maxLengthP > 0 and lengthP > maxLengthP: lengthP = maxLengthP",
              Space::light)
            .value("clipped", clipped ? 1.0 : 0.0).value("lengthP", warp.length_p);
    });
    return warp;
}

// Steps 8 to 10: PPLS Transform, light space -> PPLS.
glm::dmat4 ppls_transform(const Warp& w, Trace* trace) {
    const glm::dvec2 p = w.unit_p;
    const glm::dmat4 projection = from_rows({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0},
                                            {p.x * w.length_p, p.y * w.length_p, 0, 1});
    const glm::dmat4 z_rotation = from_rows({p.x, p.y, 0, 0}, {p.y, -p.x, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1});
    const glm::dmat4 ppls_from_light = z_rotation * projection;  // row-vector "Projection * ZRotation"
    record(trace, [&](Trace& t) {
        t.add("xpsm-8", "Projection", "w = 1 + lengthP (unitP · xy): the projection vector as the w row",
              Space::light).value("Projection", projection);
        t.add("xpsm-9", "ZRotation", "rotation about z taking unitP onto the x axis", Space::light)
            .value("ZRotation", z_rotation);
        t.add("xpsm-10", "PPLS Transform", "Projection * ZRotation (row vectors): light space -> PPLS",
              Space::ppls).value("PPLS_Transform", ppls_from_light);
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
        if (h.w < min_w) ++out.left_out;  // counted for the trace, as the seed leaves such points out
        else if (keep) out.points.push_back(glm::dvec3(h) / h.w);
    };
    for (size_t i = 0; i + 8 <= ws_corners.size(); i += 8) {
        const glm::dvec3* box = &ws_corners[i];
        double lo = INFINITY, hi = -INFINITY;
        for (int k = 0; k < 8; ++k) lo = std::min(lo, start.signed_distance(box[k])), hi = std::max(hi, start.signed_distance(box[k]));
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
    const auto body = start_warp("xpsm", in, s, setup, trace);
    if (!body) return setup;
    const std::vector<glm::dvec3> ws_receivers = corners_within(in.receivers, body->visible.bounds());
    const std::vector<glm::dvec3> ws_casters = corners_within(in.casters, body->body.bounds());
    if (ws_receivers.empty() || ws_casters.empty()) {
        fall_back_to_focused(Note{NoteKind::nothing_to_warp, "nothing to warp; focused map used"}, in,
                             *body, setup, trace);
        return setup;
    }

    // Step 1: LightSpace, origin at the viewer, z along the light.
    const glm::dmat4 light_from_world =
        light_basis(in.light.direction, stable_up_hint(in.light.direction), in.camera.position).light_from_world;
    const std::vector<glm::dvec3> ls_casters = transformed(ws_casters, light_from_world);
    const std::vector<glm::dvec3> ls_receivers = transformed(ws_receivers, light_from_world);
    // Step 2: the view vector in light space. Step 3: its xy direction.
    const glm::dvec3 v = glm::dmat3(light_from_world) * in.camera.view_direction();
    const double v_xy = glm::length(glm::dvec2(v));
    record(trace, [&](Trace& t) {
        t.add("xpsm-1", "LightSpace", "look-at along the light from the viewer: the light travels along +z",
              Space::light)
            .value("LightSpace", light_from_world)
            .shape("Casters", PointSet{ls_casters}).shape("Receivers", PointSet{ls_receivers});
        t.set_frame(Space::light, light_from_world);
        t.add("xpsm-2", "V", "the view vector in light space", Space::light).value("V", v);
        t.add("xpsm-3", "unitP", "V.xy / |V.xy|; |V.xy| < 0.1 is the miner's lamp case", Space::light)
            .value("abs_V_xy", v_xy)
            .value("unitP", v_xy > 0 ? glm::dvec2(v) / v_xy : glm::dvec2(0.0));
    });
    if (v_xy < 0.1) {
        fall_back_to_focused(Note{NoteKind::miners_lamp, "|V.xy| = " + std::to_string(v_xy) +
                                 " < 0.1, the light is almost parallel to the view; focused map used"},
                             in, *body, setup, trace);
        return setup;
    }
    const Warp warp = projection_vector(glm::dvec2(v) / v_xy, v_xy, ls_casters, ls_receivers, s, trace);
    const glm::dmat4 ppls_from_light = ppls_transform(warp, trace);  // steps 8 to 10: PPLS Transform
    record(trace, [&](Trace& t) { t.set_frame(Space::ppls, ppls_from_light * light_from_world); });

    // Steps 11 and 12: PPLS points (boxes cut at w = εW) and their boxes.
    const double min_w = s.number("epsilonW") * (1.0 - 1e-9);  // the extreme point itself stays in
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
        t.add("xpsm-11", "PPLS Casters and Receivers",
              "points * LightSpace * PPLS Transform, boxes cut where the focus interval starts; corners with w < εW "
              "counted as left out",
              Space::ppls)
            .value("casters_left_out", double(ppls_casters.left_out))
            .value("receivers_left_out", double(ppls_receivers.left_out))
            .shape("PPLS Casters", PointSet{ppls_casters.points})
            .shape("PPLS Receivers", PointSet{ppls_receivers.points});
        t.add("xpsm-12", "PPLS CastersBox, ReceiversBox",
              "AABBs of the PPLS points; the receivers' kept within the visible region's", Space::ppls)
            .shape("PPLS CastersBox", ppls_casters_box).shape("PPLS ReceiversBox", ppls_receivers_box);
        t.add("xpsm-13", "FocusRegion", "Intersect 2D (PPLS CastersBox, PPLS ReceiversBox)", Space::ppls)
            .value("MinPoint", focus_min).value("MaxPoint", focus_max);
    });
    if (ppls_casters_box.empty() || ppls_receivers_box.empty() || focus_min.x >= focus_max.x ||
        focus_min.y >= focus_max.y) {
        fall_back_to_focused(Note{NoteKind::empty_focus_region, "no caster's light rays meet a receiver in PPLS; focused map used"},
                             in, *body, setup, trace);
        return setup;
    }

    // Step 14: FocusRegionBasis. Step 15: its inverse, the unit cube transform.
    const double z_min = std::min(ppls_casters_box.min.z, ppls_receivers_box.min.z);
    const double z_max = std::max(ppls_casters_box.max.z, ppls_receivers_box.max.z);
    const Aabb focus{{focus_min, z_min}, {focus_max, z_max}};
    const glm::dmat4 ppls_from_uvz = from_rows({focus.extent().x, 0, 0, focus.min.x},  // step 14: FocusRegionBasis
                                               {0, focus.extent().y, 0, focus.min.y},
                                               {0, 0, focus.extent().z, focus.min.z}, {0, 0, 0, 1});
    const glm::dmat4 uvz_from_ppls = unit_from_box(focus);  // step 15: UnitCubeTransform
    // Steps 16 and 17: our maps stay in [0,1]^3, so NormalizedSpace is the identity.
    ShadowMap map;
    map.world_to_uvz = uvz_from_ppls * ppls_from_light * light_from_world;  // step 17: XPSM Transform
    // Step 18: bias / (MaxZ - MinZ), with the extent step 15 divides by: a flat focus region (the eye
    // at the height of a flat ground under an overhead light) has MaxZ = MinZ, widened there.
    map.z_bias_scale = uvz_from_ppls[2][2];
    setup.maps.push_back(map);
    record(trace, [&](Trace& t) {
        t.add("xpsm-14", "FocusRegionBasis", "scale (Max - Min) and offset Min, with ZMin/ZMax of both boxes",
              Space::ppls)
            .value("ZMin", z_min).value("ZMax", z_max).value("FocusRegionBasis", ppls_from_uvz)
            .shape("focus region", focus);
        t.add("xpsm-15", "UnitCubeTransform",
              "FocusRegionBasis^-1: (p - Min) / (Max - Min) (the seed's printed step-15 signs are wrong; 3.8 is right)",
              Space::unit).value("UnitCubeTransform", uvz_from_ppls);
        t.add("xpsm-16", "NormalizedSpace", "identity: maps stay in [0,1]^3 (D3D/OpenGL NDC would follow here)",
              Space::unit).value("NormalizedSpace", glm::dmat4(1.0));
        t.add("xpsm-17", "XPSM Transform", "LightSpace, PPLS Transform, UnitCubeTransform, NormalizedSpace",
              Space::unit).value("XPSM_Transform", map.world_to_uvz);
        t.add("xpsm-18", "Z bias", "Z' = (Z - bias / (MaxZ - MinZ)) / W", Space::unit)
            .value("z_bias_scale", map.z_bias_scale);
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
