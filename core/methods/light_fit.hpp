#pragma once
// Helpers shared by the methods: light-space bases and fitting a map to points.
#include <cmath>
#include <optional>
#include <string>
#include <vector>
#include <glm/glm.hpp>

#include "geometry/aabb.hpp"
#include "methods/map_method.hpp"
#include "scene/light.hpp"

namespace shadowlab {

struct LightBasis {
    glm::dmat4 light_from_world{1.0};  // rotation (and translation to `origin`): light travels along +z
    bool up_was_degenerate = false;    // the up hint was parallel to the light: another axis was used
};

// Light space for a direction: z = direction, y = `up_hint` made perpendicular to it, x = y × z.
LightBasis light_basis(const glm::dvec3& direction, const glm::dvec3& up_hint,
                       const glm::dvec3& origin = glm::dvec3(0.0));

// An up hint that does not depend on the camera (world +y, or +x for a vertical light), so that a
// map built on it stays still as the camera moves.
inline glm::dvec3 stable_up_hint(const glm::dvec3& direction) {
    return std::abs(direction.y) < 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
}

// Points transformed by an affine matrix.
std::vector<glm::dvec3> transformed(const std::vector<glm::dvec3>& points, const glm::dmat4& m);
Aabb bounds_of(const std::vector<glm::dvec3>& points);

// A box (in light space, or in PPLS after a warp) onto the map's unit cube (u, v, depth in [0,1]);
// depth = (z - min.z) / (max.z - min.z).
glm::dmat4 unit_from_box(const Aabb& box);

// An orthographic map of the light-space box `ls_box`: world_to_uvz = unit_from_box(ls_box) * light_from_world.
ShadowMap orthographic_map(const glm::dmat4& light_from_world, const Aabb& ls_box);

// The pre-division depth change per world unit moved along `direction` at the point `at`, the
// z_bias_scale of a map whose w changes along light rays (exact at `at`, first order elsewhere):
// d(p + t L) = (d_pre + t a) / (w + t c) ≈ d + t (a - d c) / w, with a, c the rows' slopes along L.
double depth_slope_along(const glm::dmat4& uvz_from_world, const glm::dvec3& direction, const glm::dvec3& at);

// A perspective map from a spot or point light that covers `points` (world), at most
// `max_half_angle_deg` off its axis. Named fallbacks: points behind the light, or wider than the
// allowed cone (the map then covers only the cone).
struct PerspectiveFit {
    ShadowMap map;
    glm::dmat4 light_from_world{1.0};  // light view: looks down +z here, like the directional case
    Aabb light_box;                    // tangent-space x, y and distance z of the covered points
    std::optional<Note> fallback;
};
PerspectiveFit perspective_map(const Light& light, const glm::dvec3& axis, const std::vector<glm::dvec3>& points,
                               double max_half_angle_deg);

// The perspective map of a light-space frustum given as tangent bounds (x/z, y/z in min.xy..max.xy)
// and distances along z (near min.z, far max.z): u, v the tangents across the bounds, depth
// f (z - n) / ((f - n) z), growing with distance.
ShadowMap perspective_map_of(const glm::dmat4& light_from_world, const Aabb& tangent_box);

}  // namespace shadowlab
