// Perspective Shadow Maps (Stamminger and Drettakis 2002) with Kozlov's remedies ("Perspective
// shadow maps: care and feeding", GPU Gems 2004). The map is built in the camera's post-perspective
// space (PPS), where the directional light becomes a point light (or stays directional when it is
// perpendicular to the view). A spot or point light goes through P V like any point (Stamminger and
// Drettakis's recipe takes the light's homogeneous position): a point light there, directional on the
// virtual camera's plane w = 0, and with its depth order inverted behind it, as Kozlov's directional
// light behind the viewer has.
#include "methods/psm.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "math/matrix.hpp"
#include "methods/focused.hpp"
#include "methods/light_fit.hpp"
#include "methods/map_fit.hpp"
#include "methods/step_figures.hpp"
#include "methods/warp_common.hpp"

namespace shadowlab {
namespace {

// The widest light cone a PPS point light may need before the map is useless.
constexpr double kMaxHalfAngleDeg = 80.0;

// PPS, the virtual camera's post-perspective space, is its clip space divided by w: as homogeneous
// matrices, clip_from_x and pps_from_x are the same (the trace shows PPS as Space::ppls).
struct VirtualCamera {
    glm::dmat4 pps_from_world;  // P V of the virtual camera: world -> clip, PPS after division by w
    glm::dvec3 eye;
    double slide, near, far;
};

// Kozlov's first remedy: slide the camera back along its axis until every point to cover (casters
// behind the viewer included) lies in front of it, and pull near and far to those points.
VirtualCamera slid_back_camera(const Camera& camera, const std::vector<glm::dvec3>& ws_points) {
    const glm::dvec3 dir = camera.view_direction();
    double min_depth = INFINITY, max_depth = -INFINITY;
    for (const glm::dvec3& p : ws_points) {
        min_depth = std::min(min_depth, glm::dot(p - camera.position, dir));
        max_depth = std::max(max_depth, glm::dot(p - camera.position, dir));
    }
    const double margin = std::max(camera.near, 1e-3 * (max_depth - min_depth));
    const double slide = std::max(0.0, margin - min_depth);
    VirtualCamera v;
    v.slide = slide;
    v.eye = camera.position - slide * dir;
    v.near = std::max(min_depth + slide, margin);
    v.far = std::max(max_depth + slide, v.near * (1 + 1e-6));
    const glm::dmat4 view_from_world = glm::lookAt(v.eye, v.eye + dir, camera.up);
    const glm::dmat4 clip_from_view = glm::perspective(glm::radians(camera.fov_y_deg), camera.aspect, v.near, v.far);
    v.pps_from_world = clip_from_view * view_from_world;
    return v;
}

// The orthographic fit in PPS for a light that stays directional there (perpendicular to the view).
// light_basis and orthographic_map are given PPS for their world here.
ShadowMap pps_orthographic(const glm::dvec3& pps_direction, const std::vector<glm::dvec3>& pps_points,
                           const glm::dmat4& pps_from_world) {
    const glm::dmat4 light_from_pps = light_basis(pps_direction, stable_up_hint(pps_direction)).light_from_world;
    ShadowMap map = orthographic_map(light_from_pps, bounds_of(transformed(pps_points, light_from_pps)));
    const glm::dmat4 uvz_from_pps = map.world_to_uvz;
    map.world_to_uvz = uvz_from_pps * pps_from_world;
    return map;
}

// The PPS light's fit redone to reach the points of `pps_within` (the body within its frustum) that lie
// past its far end (past its near end when inverted: depth then runs the other way): visible points
// beyond a spot's cone that the map's square takes in. The fit stays when none does, or when the
// refit would need a fallback.
PerspectiveFit reaching_past_far(const PerspectiveFit& fit, const Light& pps_light, const glm::dvec3& axis,
                                 std::vector<glm::dvec3> pps_points, const std::vector<glm::dvec3>& pps_within,
                                 bool inverted) {
    const size_t fitted = pps_points.size();
    for (const glm::dvec3& p : pps_within) {
        const double z = transform_point(fit.light_from_world, p).z;
        if (inverted ? z < fit.light_box.min.z : z > fit.light_box.max.z) pps_points.push_back(p);
    }
    if (pps_points.size() == fitted) return fit;
    PerspectiveFit reaching = perspective_map(pps_light, axis, pps_points, kMaxHalfAngleDeg);
    return reaching.fallback ? fit : reaching;
}

}  // namespace

std::vector<SettingSpec> psm_settings() { return {body_kernel_setting()}; }

ShadowSetup compute_psm(const ShadowInputs& in, const Settings& s, Trace* trace) {
    ShadowSetup setup;
    const auto region = start_warp_in_reach("psm", in, s, setup, trace);
    if (!region) return setup;
    const std::vector<glm::dvec3>& ws_body = region->ws_points;  // B, or a spot light's reach of B

    const VirtualCamera camera = slid_back_camera(in.camera, ws_body);
    const ProjectedPoints pps_body = project(ws_body, camera.pps_from_world, 0.0);
    // The light in PPS (homogeneous): the image of its position, or of the point at infinity it comes from.
    const glm::dvec4 pps_light = camera.pps_from_world * in.light.homogeneous();
    const double w_ratio = pps_light.w / glm::length(glm::dvec3(pps_light));
    record(trace, [&](Trace& t) {
        // The virtual camera's frustum is PPS's cube [-1,1]^3 taken back into the world.
        const Aabb pps_cube{glm::dvec3(-1.0), glm::dvec3(1.0)};
        Step& slide = t.add("psm-virtual-camera", "Virtual camera slid back (Kozlov)",
                            "eye moved back by δ along the view so every caster is in front; near and far pulled to "
                            "the points",
                            Space::world)
                          .value("slide", camera.slide)
                          .value("eye", camera.eye)
                          .value("near", camera.near)
                          .value("far", camera.far)
                          .shape("virtual frustum", preimage_of_box(camera.pps_from_world, pps_cube), Role::view)
                          .shape("B", PointSet{ws_body}, Role::focus)
                          .shape("eye", PointSet{{in.camera.position, camera.eye}}, Role::view);
        if (camera.slide > 0.0)
            draw_dimension(slide.shape("virtual eye label", Label{camera.eye, "virtual eye"}, Role::view), "δ",
                           camera.eye, in.camera.position);
        else
            slide.shape("δ label", Label{in.camera.position, "δ = 0: every point already in front of the eye"});
        t.add("psm-pps", "Post-perspective space",
              "p' = (P V p) / w of the virtual camera: the view frustum becomes a cube", Space::ppls)
            .value("view_projection", camera.pps_from_world)
            .shape("PPS body", PointSet{pps_body.points}, Role::focus)
            .shape("unit cube", pps_cube, Role::view)
            .shape("unit cube label", Label{{-1.0, 1.0, -1.0}, "view frustum → [-1,1]³"}, Role::view);
        t.set_frame(Space::view, glm::lookAt(camera.eye, camera.eye + in.camera.view_direction(), in.camera.up));
        t.set_frame(Space::ppls, camera.pps_from_world);
        Step& light = t.add("psm-light", "Light in PPS",
                            "L' = P V L, L = (-dir, 0) or (position, 1): w ≈ 0 directional, w > 0 a point light, "
                            "w < 0 behind the viewer",
                            Space::ppls)
                          .value("L_pps", pps_light)
                          .value("w_over_length", w_ratio);
        const glm::dvec3 pps_centre = bounds_of(pps_body.points).center();
        if (std::abs(w_ratio) < 1e-9) {  // still directional: L' as an arrow arriving at the body
            draw_arrow(light, "L'", pps_centre + glm::normalize(glm::dvec3(pps_light)), -glm::dvec3(pps_light), 1.0,
                       Role::light);
        } else {
            const glm::dvec3 pps_position = glm::dvec3(pps_light) / pps_light.w;
            light.shape("L'", PointSet{{pps_position}}, Role::light)
                .shape("L' label",
                       Label{pps_position, pps_light.w > 0.0 ? "L': a point light" : "L': behind the viewer (w < 0)"},
                       Role::light)
                .shape("L' to B", SegmentSet{{{pps_position, pps_centre}}}, Role::light);
        }
    });

    ShadowMap map;
    if (std::abs(w_ratio) < 1e-9) {  // light perpendicular to the view: still directional in PPS
        map = pps_orthographic(-glm::dvec3(pps_light), pps_body.points, camera.pps_from_world);
        record(trace, [&](Trace& t) {
            Step& fit = t.add("psm-light-orthographic", "Orthographic light in PPS",
                              "light perpendicular to the view: it stays directional in PPS, fitted like a focused map",
                              Space::ppls)
                            .value("L_pps_direction", -glm::dvec3(pps_light))
                            .shape("map volume",
                                   preimage_of_box(map.world_to_uvz * glm::inverse(camera.pps_from_world),
                                                   Aabb{glm::dvec3(0.0), glm::dvec3(1.0)}),
                                   Role::map);
            draw_arrow(fit, "L'", bounds_of(pps_body.points).center(), -glm::dvec3(pps_light), 1.0, Role::light);
            const glm::dmat4 light_from_pps =
                light_basis(-glm::dvec3(pps_light), stable_up_hint(-glm::dvec3(pps_light))).light_from_world;
            t.set_frame(Space::light, light_from_pps * camera.pps_from_world);
        });
    } else {
        Light pps_point_light;
        pps_point_light.type = LightType::point;
        pps_point_light.position = glm::dvec3(pps_light) / pps_light.w;
        glm::dvec3 pps_centre{0.0};
        for (const glm::dvec3& p : pps_body.points) pps_centre += p / double(pps_body.points.size());
        const glm::dvec3 axis = glm::normalize(pps_centre - pps_point_light.position);
        PerspectiveFit fit = perspective_map(pps_point_light, axis, pps_body.points, kMaxHalfAngleDeg);
        if (fit.fallback) {
            // A directional light's image reaches the region only when it nearly runs along the view; a spot
            // or point light's when it stands in or beside what it must cover.
            const NoteKind kind = in.light.is_directional() ? NoteKind::parallel_light : NoteKind::light_on_region;
            fall_back_to_focused(Note{kind, "the PPS light lies on the region to cover (" + describe(*fit.fallback) +
                                                "); focused map used"},
                                 in, region->body, setup, trace);
            return setup;
        }
        // Kozlov's second remedy: a light behind the viewer is a sink in PPS; its rays run toward
        // the PPS light, so depth grows toward it (the inverted projection): d' = 1 - d.
        const bool inverted = pps_light.w < 0.0;
        if (!in.light.is_directional()) {
            const std::vector<glm::dvec3> ws_within =
                body_within_frustum(region->body.body, fit.map.world_to_uvz * camera.pps_from_world, in.light.position);
            fit = reaching_past_far(fit, pps_point_light, axis, pps_body.points,
                                    project(ws_within, camera.pps_from_world, 0.0).points, inverted);
        }
        const glm::dmat4& light_from_pps = fit.light_from_world;  // perspective_map was given PPS for its world
        map = fit.map;
        glm::dmat4 uvz_from_pps = fit.map.world_to_uvz;  // likewise: its map takes PPS to uvz
        if (inverted) uvz_from_pps = from_rows({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, -1, 1}, {0, 0, 0, 1}) * uvz_from_pps;
        map.world_to_uvz = uvz_from_pps * camera.pps_from_world;
        record(trace, [&](Trace& t) {
            // The PPS light's frustum: the unit cube taken back through the fit (before any inversion of depth).
            const Frustum light_frustum = map_volume(fit.map);
            t.add("psm-light-frustum", inverted ? "Inverted projection (Kozlov)" : "Light frustum in PPS",
                  inverted ? "light behind the viewer: rays converge on the PPS light, depth reversed (d' = 1 - d)"
                           : "perspective from the PPS light covering the body",
                  Space::ppls)
                .value("light_position", pps_point_light.position)
                .value("pps_to_light", light_from_pps)
                .value("near", fit.light_box.min.z)
                .value("far", fit.light_box.max.z)
                .value("inverted", inverted ? 1.0 : 0.0)
                .shape("light frustum", light_frustum, Role::map)
                .shape("near and far", near_and_far_faces(light_frustum), Role::map)
                .shape("L'", PointSet{{pps_point_light.position}}, Role::light)
                .shape("L' label", Label{pps_point_light.position, "L'"}, Role::light);
            t.set_frame(Space::light, light_from_pps * camera.pps_from_world);
        });
    }
    // Bias in world units along the light, exact at the centre of the visible region.
    const glm::dvec3 visible_centre = region->body.visible.centroid();
    map.z_bias_scale = depth_slope_along(map.world_to_uvz, light_ray_at(in.light, visible_centre), visible_centre);
    setup.maps.push_back(map);
    record_output(setup, ws_body, trace);
    return setup;
}

}  // namespace shadowlab
