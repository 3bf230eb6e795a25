// Perspective Shadow Maps (Stamminger and Drettakis 2002) with Kozlov's remedies ("Perspective
// shadow maps: care and feeding", GPU Gems 2004). The map is built in the camera's post-perspective
// space (PPS), where the directional light becomes a point light (or stays directional when it is
// perpendicular to the view).
#include "methods/psm.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "math/matrix.hpp"
#include "methods/fallbacks.hpp"
#include "methods/light_fit.hpp"
#include "methods/map_fit.hpp"
#include "methods/warp_common.hpp"

namespace shadowlab {
namespace {

// The widest light cone a PPS point light may need before the map is useless.
constexpr double kMaxHalfAngleDeg = 80.0;

struct VirtualCamera {
    glm::dmat4 view_projection;  // world -> clip of the virtual camera
    glm::dvec3 eye;
    double slide, near, far;
};

// Kozlov's first remedy: slide the camera back along its axis until every point to cover (casters
// behind the viewer included) lies in front of it, and pull near and far to those points.
VirtualCamera slid_back_camera(const Camera& camera, const std::vector<glm::dvec3>& points) {
    const glm::dvec3 dir = camera.view_direction();
    double min_depth = INFINITY, max_depth = -INFINITY;
    for (const glm::dvec3& p : points) {
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
    const glm::dmat4 view = glm::lookAt(v.eye, v.eye + dir, camera.up);
    v.view_projection = glm::perspective(glm::radians(camera.fov_y_deg), camera.aspect, v.near, v.far) * view;
    return v;
}

// The orthographic fit in PPS for a light that stays directional there (perpendicular to the view).
ShadowMap pps_orthographic(const glm::dvec3& pps_direction, const std::vector<glm::dvec3>& pps_points,
                           const glm::dmat4& view_projection) {
    const LightBasis basis = light_basis(pps_direction, stable_up_hint(pps_direction));
    ShadowMap map = orthographic_map(basis.world_to_light, bounds_of(transformed(pps_points, basis.world_to_light)));
    map.world_to_uvz = map.world_to_uvz * view_projection;
    return map;
}

}  // namespace

ShadowSetup compute_psm(const ShadowInputs& in, const Settings& s, Trace* trace) {
    ShadowSetup setup;
    const auto body = start_warp("psm", in, s, setup, trace);
    if (!body) return setup;
    const std::vector<glm::dvec3>& points = body->body.vertices;

    const VirtualCamera camera = slid_back_camera(in.camera, points);
    const ProjectedPoints pps = project(points, camera.view_projection, 0.0);
    // The light in PPS: the image of the point at infinity it comes from.
    const glm::dvec4 light = camera.view_projection * in.light.homogeneous();
    const double w_ratio = light.w / glm::length(glm::dvec3(light));
    record(trace, [&](Trace& t) {
        t.add("psm-virtual-camera", "Virtual camera slid back (Kozlov)",
              "eye moved back by δ along the view so every caster is in front; near and far pulled to the points",
              Space::view)
            .value("slide", camera.slide).value("eye", camera.eye).value("near", camera.near).value("far", camera.far);
        t.add("psm-pps", "Post-perspective space", "p' = (P V p) / w of the virtual camera: the view frustum becomes a cube",
              Space::ppls)
            .value("view_projection", camera.view_projection)
            .shape("PPS body", PointSet{pps.points}).shape("unit cube", Aabb{glm::dvec3(-1.0), glm::dvec3(1.0)});
        t.set_frame(Space::view, glm::lookAt(camera.eye, camera.eye + in.camera.view_direction(), in.camera.up));
        t.set_frame(Space::ppls, camera.view_projection);
        t.add("psm-light", "Light in PPS", "L' = P V (-L, 0): w ≈ 0 directional, w > 0 a point light, w < 0 behind the viewer",
              Space::ppls)
            .value("L_pps", light).value("w_over_length", w_ratio);
    });

    ShadowMap map;
    if (std::abs(w_ratio) < 1e-9) {  // light perpendicular to the view: still directional in PPS
        map = pps_orthographic(-glm::dvec3(light), pps.points, camera.view_projection);
        record(trace, [&](Trace& t) {
            t.add("psm-light-orthographic", "Orthographic light in PPS",
                  "light perpendicular to the view: it stays directional in PPS, fitted like a focused map", Space::ppls)
                .value("L_pps_direction", -glm::dvec3(light));
            t.set_frame(Space::light, light_basis(-glm::dvec3(light), stable_up_hint(-glm::dvec3(light))).world_to_light *
                                          camera.view_projection);
        });
    } else {
        Light pps_light;
        pps_light.type = LightType::point;
        pps_light.position = glm::dvec3(light) / light.w;
        glm::dvec3 centre{0.0};
        for (const glm::dvec3& p : pps.points) centre += p / double(pps.points.size());
        const PerspectiveFit fit = perspective_map(pps_light, glm::normalize(centre - pps_light.position), pps.points,
                                                   kMaxHalfAngleDeg);
        if (fit.fallback) {
            fall_back_to_focused(fallback::named(fallback::parallel_light,
                                                 "the PPS light lies on the region to cover (" + *fit.fallback +
                                                     "); focused map used"),
                                 in, *body, setup, trace);
            return setup;
        }
        map = fit.map;
        // Kozlov's second remedy: a light behind the viewer is a sink in PPS; its rays run toward
        // the PPS light, so depth grows toward it (the inverted projection): d' = 1 - d.
        const bool inverted = light.w < 0.0;
        if (inverted) map.world_to_uvz = from_rows({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, -1, 1}, {0, 0, 0, 1}) * map.world_to_uvz;
        map.world_to_uvz = map.world_to_uvz * camera.view_projection;
        record(trace, [&](Trace& t) {
            t.add("psm-light-frustum", inverted ? "Inverted projection (Kozlov)" : "Light frustum in PPS",
                  inverted ? "light behind the viewer: rays converge on the PPS light, depth reversed (d' = 1 - d)"
                           : "perspective from the PPS light covering the body",
                  Space::ppls)
                .value("light_position", pps_light.position).value("pps_to_light", fit.world_to_light)
                .value("near", fit.light_box.min.z).value("far", fit.light_box.max.z)
                .value("inverted", inverted ? 1.0 : 0.0);
            t.set_frame(Space::light, fit.world_to_light * camera.view_projection);
        });
    }
    // Bias in world units along the light, exact at the centre of the visible region.
    map.z_bias_scale = depth_slope_along(map.world_to_uvz, in.light.direction, body->visible.centroid());
    setup.maps.push_back(map);
    record_output(setup, points, trace);
    return setup;
}

}  // namespace shadowlab
