#include "methods/light_fit.hpp"

#include <algorithm>
#include <cmath>

#include "math/matrix.hpp"

namespace shadowlab {

LightBasis light_basis(const glm::dvec3& direction, const glm::dvec3& up_hint, const glm::dvec3& origin) {
    const glm::dvec3 z = glm::normalize(direction);
    LightBasis basis;
    glm::dvec3 y = up_hint - glm::dot(up_hint, z) * z;
    if (!(glm::length(y) > 1e-9 * glm::length(up_hint))) {
        basis.up_was_degenerate = true;
        y = std::abs(z.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        y -= glm::dot(y, z) * z;
    }
    y = glm::normalize(y);
    const glm::dvec3 x = glm::cross(y, z);
    basis.light_from_world =
        from_rows({x, -glm::dot(x, origin)}, {y, -glm::dot(y, origin)}, {z, -glm::dot(z, origin)}, {0, 0, 0, 1});
    return basis;
}

std::vector<glm::dvec3> transformed(const std::vector<glm::dvec3>& points, const glm::dmat4& m) {
    std::vector<glm::dvec3> out;
    out.reserve(points.size());
    for (const glm::dvec3& p : points) out.push_back(glm::dvec3(m * glm::dvec4(p, 1.0)));
    return out;
}

Aabb bounds_of(const std::vector<glm::dvec3>& points) {
    Aabb box;
    for (const glm::dvec3& p : points) box.extend(p);
    return box;
}

// Extents too small to divide by are widened symmetrically (a flat box still gets a valid map).
static glm::dvec3 safe_extent(const Aabb& box) {
    const double floor = 1e-12 * std::max(1.0, glm::length(glm::abs(box.min) + glm::abs(box.max)));
    return glm::max(box.extent(), glm::dvec3(floor));
}

glm::dmat4 unit_from_box(const Aabb& b) {
    const glm::dvec3 e = safe_extent(b);
    return from_rows({1 / e.x, 0, 0, -b.min.x / e.x}, {0, 1 / e.y, 0, -b.min.y / e.y}, {0, 0, 1 / e.z, -b.min.z / e.z},
                     {0, 0, 0, 1});
}

ShadowMap orthographic_map(const glm::dmat4& light_from_world, const Aabb& ls_box) {
    ShadowMap map;
    map.world_to_uvz = unit_from_box(ls_box) * light_from_world;
    map.z_bias_scale = 1.0 / safe_extent(ls_box).z;
    return map;
}

double depth_slope_along(const glm::dmat4& uvz_from_world, const glm::dvec3& direction, const glm::dvec3& at) {
    const double a = glm::dot(glm::dvec3(row(uvz_from_world, 2)), direction);  // the depth row's slope along L
    const double c = glm::dot(glm::dvec3(row(uvz_from_world, 3)), direction);  // the w row's
    const glm::dvec4 h = uvz_from_world * glm::dvec4(at, 1.0);
    return a - (h.z / h.w) * c;
}

PerspectiveFit perspective_map(const Light& light, const glm::dvec3& axis, const std::vector<glm::dvec3>& points,
                               double max_half_angle_deg) {
    PerspectiveFit fit;
    const glm::dvec3 up_hint = std::abs(axis.y) < 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    fit.light_from_world = light_basis(axis, up_hint, light.position).light_from_world;
    const double max_tan = std::tan(glm::radians(max_half_angle_deg));

    size_t behind = 0, outside_cone = 0;
    const std::vector<glm::dvec3> ls_points = transformed(points, fit.light_from_world);
    double far = 0.0;
    for (const glm::dvec3& p : ls_points) far = std::max(far, p.z);
    const double min_near = std::max(far, 1e-9) * 1e-6;  // keeps the depth mapping finite
    for (const glm::dvec3& p : ls_points) {
        if (p.z <= min_near) {
            ++behind;
            continue;
        }
        glm::dvec2 t = glm::dvec2(p) / p.z;
        if (std::abs(t.x) > max_tan || std::abs(t.y) > max_tan) ++outside_cone;
        t = glm::clamp(t, -max_tan, max_tan);
        fit.light_box.extend({t, p.z});
    }
    if (fit.light_box.empty()) fit.light_box = {{-max_tan, -max_tan, min_near}, {max_tan, max_tan, 2 * min_near}};
    if (behind > 0)
        fit.fallback = Note{
            NoteKind::behind_light,
            std::to_string(behind) + " left out: one perspective map cannot cover them (an omnidirectional map would)"};
    else if (outside_cone > 0)
        fit.fallback = Note{NoteKind::outside_cone, std::to_string(outside_cone) + " clamped to the cone"};

    fit.map = perspective_map_of(fit.light_from_world, fit.light_box);
    return fit;
}

ShadowMap perspective_map_of(const glm::dmat4& light_from_world, const Aabb& tangent_box) {
    const Aabb& b = tangent_box;
    const glm::dvec3 e = safe_extent(b);
    const double n = b.min.z, f = std::max(b.max.z, n * (1 + 1e-9));
    // u = (x/z - t0) / extent, d = f (z - n) / ((f - n) z): depth grows with distance.
    const glm::dmat4 uvz_from_light = from_rows({1 / e.x, 0, -b.min.x / e.x, 0}, {0, 1 / e.y, -b.min.y / e.y, 0},
                                                {0, 0, f / (f - n), -f * n / (f - n)}, {0, 0, 1, 0});
    return {.world_to_uvz = uvz_from_light * light_from_world, .z_bias_scale = f / (f - n)};
}

}  // namespace shadowlab
