#include "maps/linear_projection.hpp"

#include <cmath>

namespace shadowlab {
namespace {

glm::dvec4 homogeneous(const ShadowMap& map, const glm::dvec3& world) {
    return map.world_to_uvz * glm::dvec4(world, 1.0);
}

glm::dvec3 world_of(const ShadowMap& map, const glm::dvec3& uvz) {
    const glm::dvec4 h = glm::inverse(map.world_to_uvz) * glm::dvec4(uvz, 1.0);
    return glm::dvec3(h) / h.w;
}

// s = 1 − d_pre / w = (w − d_pre) / w: the depth row replaced by the combined row, w's less d_pre's.
ShadowMap reversed_depth(const ShadowMap& map) {
    ShadowMap reversed = map;
    for (int column = 0; column < 4; ++column)
        reversed.world_to_uvz[column][2] = map.world_to_uvz[column][3] - map.world_to_uvz[column][2];
    return reversed;
}

// (u, v) = h.xy / h.w with h = M (p, 1); along the direction h changes by M (direction, 0).
glm::dvec2 uv_derivative(const ShadowMap& map, const glm::dvec3& p, const glm::dvec3& direction) {
    const glm::dvec4 h = map.world_to_uvz * glm::dvec4(p, 1.0);
    const glm::dvec4 dh = map.world_to_uvz * glm::dvec4(direction, 0.0);
    return (glm::dvec2(dh) * h.w - glm::dvec2(h) * dh.w) / (h.w * h.w);
}

double depth_slope(const ShadowMap& map, const glm::dvec3& l, const glm::dvec3& p) {
    const glm::dmat4& m = map.world_to_uvz;
    const glm::dvec4 h = m * glm::dvec4(p, 1.0);
    const double a = glm::dot(glm::dvec3(m[0][2], m[1][2], m[2][2]), l);  // d_pre's slope along l
    const double c = glm::dot(glm::dvec3(m[0][3], m[1][3], m[2][3]), l);  // w's slope along l
    return (a * h.w - h.z * c) / (h.w * h.w);                             // the quotient rule on d_pre / w
}

// At p - s l the map holds (h.z - s dh.z) / (h.w - s dh.w); set it to `depth` and solve for s.
double distance_back_to_depth(const ShadowMap& map, const glm::dvec3& l, const glm::dvec3& p, double depth) {
    const glm::dvec4 h = map.world_to_uvz * glm::dvec4(p, 1.0);
    const glm::dvec4 dh = map.world_to_uvz * glm::dvec4(l, 0.0);
    const double s = (h.z - depth * h.w) / (dh.z - depth * dh.w);
    return std::isfinite(s) && s >= 0.0 ? s : INFINITY;
}

std::vector<NamedValue> matrix(const ShadowMap& map) { return {{"world_to_uvz", map.world_to_uvz}}; }

// A cube face is a linear map numbered by its face: the same mapping, named apart.
constexpr ProjectionKind linear_kind(const char* name, bool numbered_face) {
    return {.name = name,
            .homogeneous = homogeneous,
            .world_of = world_of,
            .reversed_depth = reversed_depth,
            .clip_distance = nullptr,
            .edge_sagitta = nullptr,
            .uv_derivative = uv_derivative,
            .depth_slope = depth_slope,
            .distance_back_to_depth = distance_back_to_depth,
            .parameters = matrix,
            .numbered_face = numbered_face,
            .glsl = "linear_projection",
            .glsl_prefix = "shadowLinear"};
}

}  // namespace

constinit const ProjectionKind linear_projection = linear_kind("linear", false);
constinit const ProjectionKind cube_face_projection = linear_kind("cube face", true);

}  // namespace shadowlab
