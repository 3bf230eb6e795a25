// Light Space Perspective Shadow Maps (Wimmer, Scherzer, Purgathofer 2004; seeds 001 and 004).
// In light space, with y along the view direction made perpendicular to the light, a perspective
// warp looks along y from a centre C at distance n before the body B. Light rays (along z) stay
// parallel under it, so the map is an orthographic fit in the warped space.
#include "methods/lispsm.hpp"

#include <cmath>

#include "math/matrix.hpp"
#include "methods/fallbacks.hpp"
#include "methods/focused.hpp"
#include "methods/light_fit.hpp"
#include "methods/map_fit.hpp"
#include "methods/warp_common.hpp"

namespace shadowlab {

double lispsm_n(double z_n, double z_f, double sin_gamma, double eta) {
    const double ratio = std::pow(z_f / z_n, (1.0 + eta) / 2.0);  // the warp's far / near
    return (z_f - z_n) / (ratio - 1.0) / sin_gamma;
}

namespace {

// A warp weaker than this (n this many times the body's depth: under 0.01% of distortion) is none.
constexpr double kNoWarp = 1e4;

// The perspective along +y from `centre`: x' = x/y, z' = z/y, y' = f (y - n) / ((f - n) y), all
// relative to the centre; light rays (along z) keep their x', y'.
glm::dmat4 warp_matrix(const glm::dvec3& centre, double n, double f) {
    const glm::dmat4 to_centre = from_rows({1, 0, 0, -centre.x}, {0, 1, 0, -centre.y}, {0, 0, 1, -centre.z}, {0, 0, 0, 1});
    const glm::dmat4 perspective = from_rows({1, 0, 0, 0}, {0, f / (f - n), 0, -f * n / (f - n)}, {0, 0, 1, 0}, {0, 1, 0, 0});
    return perspective * to_centre;
}

}  // namespace

ShadowSetup compute_lispsm(const ShadowInputs& in, const Settings& s, Trace* trace) {
    ShadowSetup setup;
    const auto body = start_warp("lispsm", in, s, setup, trace);
    if (!body) return setup;

    // Light space with y along the view direction made perpendicular to the light.
    const glm::dvec3 view = in.camera.view_direction();
    const double sin_gamma = glm::length(glm::cross(view, in.light.direction));
    const LightBasis basis = light_basis(in.light.direction, view);
    const std::vector<glm::dvec3> light_body = transformed(body->body.vertices, basis.world_to_light);
    const Aabb body_box = bounds_of(light_body);
    // n_opt from the eye's near plane and the body's depth seen along the view (Wimmer's z_f).
    const double z_n = in.camera.near;
    const double depth = body_box.extent().y;
    const double z_f = z_n + depth * sin_gamma;
    const double eta = s.number("eta");
    const double n = s.number("n") > 0.0 ? s.number("n") : lispsm_n(z_n, z_f, sin_gamma, eta);
    record(trace, [&](Trace& t) {
        t.add("light-space", "Light space", "z = light direction, y = view direction made perpendicular to it",
              Space::light)
            .value("world_to_light", basis.world_to_light)
            .shape("B", PointSet{light_body}).shape("B box", body_box);
        t.set_frame(Space::light, basis.world_to_light);
        t.add("gamma", "Angle γ", "sin γ = |view × light|: 1 when the light is perpendicular to the view",
              Space::light)
            .value("sin_gamma", sin_gamma).value("gamma_deg", glm::degrees(std::asin(std::min(1.0, sin_gamma))));
        t.add("n-opt", "n_opt", "n = (z_n + sqrt(z_n z_f)) / sin γ, z_f = z_n + depth(B) sin γ; Lloyd's η: "
              "warp far/near = (z_f/z_n)^((1+η)/2)", Space::light)
            .value("z_n", z_n).value("z_f", z_f).value("eta", eta).value("n", n)
            .value("n_overridden", s.number("n") > 0.0 ? 1.0 : 0.0);
    });
    if (!(n < kNoWarp * depth)) {  // also catches n = ∞ and NaN at γ = 0
        if (eta > -1.0 && s.number("n") <= 0.0)
            add_fallback(setup, fallback::named(fallback::parallel_light,
                                                "sin γ = " + std::to_string(sin_gamma) +
                                                    ": the warp has faded to nothing; focused map used"));
        fit_focused(in, *body, setup, trace);
        return setup;
    }

    // The warp frustum: centre n before the body's near face, at the eye's x and z.
    const glm::dvec3 eye = transform_point(basis.world_to_light, in.camera.position);
    const glm::dvec3 centre{eye.x, body_box.min.y - n, eye.z};
    const glm::dmat4 warp = warp_matrix(centre, n, n + depth);
    const ProjectedPoints warped = project(body->body.vertices, warp * basis.world_to_light, 0.0);
    const Aabb warped_box = bounds_of(warped.points);
    ShadowMap map;
    map.world_to_uvz = box_to_unit_cube(warped_box) * warp * basis.world_to_light;
    map.z_bias_scale = 1.0 / warped_box.extent().z;
    setup.maps.push_back(map);
    record(trace, [&](Trace& t) {
        t.add("warp-frustum", "Warp frustum", "centre C = (eye x, near face of B - n, eye z), near n, far n + depth(B)",
              Space::light)
            .value("C", centre).value("near", n).value("far", n + depth)
            .shape("C", PointSet{{centre}});
        t.add("warp", "Perspective warp P", "x' = x/y, y' = f(y - n)/((f - n) y), z' = z/y about C", Space::ppls)
            .value("P", warp)
            .shape("warped B", PointSet{warped.points}).shape("warped box", warped_box);
        t.set_frame(Space::ppls, warp * basis.world_to_light);
        t.add("unit-cube", "Unit cube transform", "(p - min) / (max - min) over the warped body", Space::unit)
            .value("warped_to_unit", box_to_unit_cube(warped_box));
    });
    record_output(setup, body->body.vertices, trace);
    return setup;
}

}  // namespace shadowlab
