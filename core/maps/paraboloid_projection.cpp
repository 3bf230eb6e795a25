// The paraboloid's mapping, its inverse, its plane, its derivatives and the sagitta of its images of
// straight edges in closed form: a straight edge and the map's centre span a plane through the centre,
// whose great circle the paraboloid (a stereographic projection from the back pole) maps to a circle
// of the disc; the edge's image is an arc of it. Exact, where sampling points along the edge would
// only approach the arc's farthest point from below; tests/paraboloid_edges_test.cpp samples the edge
// finely and finds the same value.
#include "maps/paraboloid_projection.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

namespace shadowlab {
namespace {

// 1 + d.z at or below this: the back pole, where the disc coordinates leave every bound.
constexpr double kSingular = 1e-12;

glm::dvec3 in_frame(const Paraboloid& p, const glm::dvec3& world) { return p.frame_from_world * (world - p.centre); }

// Seed 002 normalizes the vector before assigning it and tests z < 0 in both of its lookup
// branches; here each hemisphere is its own map with its own frame (the back one turned half a
// turn about y), so one formula, (d.x, d.y) / (1 + d.z), serves both.
glm::dvec4 homogeneous(const ShadowMap& map, const glm::dvec3& world) {
    const Paraboloid& p = map.paraboloid;
    const glm::dvec3 q = in_frame(p, world);
    const double distance = glm::length(q);
    if (!(distance > 0.0)) return glm::dvec4(0.0);
    const glm::dvec3 d = q / distance;
    const double denominator = 1.0 + d.z;
    if (!(denominator > kSingular)) return glm::dvec4(0.0);  // straight behind: the map's singular point
    const glm::dvec2 uv = (glm::dvec2(d.x, d.y) / denominator + 1.0) / 2.0;
    return glm::dvec4(uv, (distance - p.near) / (p.far - p.near), 1.0);
}

glm::dvec3 uvz_of(const ShadowMap& map, const glm::dvec3& world) {
    const glm::dvec4 h = homogeneous(map, world);
    return glm::dvec3(h) / h.w;
}

// Back along the direction (u, v) sees, at the distance d names.
glm::dvec3 world_of(const ShadowMap& map, const glm::dvec3& uvz) {
    const Paraboloid& p = map.paraboloid;
    const glm::dvec3 direction = direction_of(2.0 * glm::dvec2(uvz) - 1.0);
    return p.centre + glm::transpose(p.frame_from_world) * direction * (p.near + uvz.z * (p.far - p.near));
}

// The signed distance to the hemisphere's plane (>= 0: its side).
double clip_distance(const ShadowMap& map, const glm::dvec3& world) { return in_frame(map.paraboloid, world).z; }

glm::dvec2 disc_at(const glm::dvec3& q) { return disc_of(glm::normalize(q)); }

bool lexicographically_less(const glm::dvec3& a, const glm::dvec3& b) {
    return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
}

// The sagitta of the image of the segment between two frame points on the map's side (z >= 0). With
// n the unit normal of the plane through the centre and both points, the inverse mapping turns n . d
// = 0 into x² + y² - 2 (n_x x + n_y y) / n_z - 1 = 0: a circle of radius r = 1 / |n_z| (a line through
// the disc's centre when n_z = 0). Inside the unit disc the arc is at most a half circle, so a chord of
// half-length h bows by r - sqrt(r² - h²) = h² / (r + sqrt(r² - h²)), the form that stays exact as r
// grows without bound.
double arc_sagitta(const glm::dvec3& qa, const glm::dvec3& qb) {
    const glm::dvec3 normal = glm::cross(qa, qb);
    const double length = glm::length(normal);
    if (!(length > 0.0)) return 0.0;  // on one ray from the centre: a radial segment, straight in the disc
    const double curvature = std::abs(normal.z) / length;  // 1 / r
    const double h = glm::distance(disc_at(qa), disc_at(qb)) / 2.0;
    return h * h * curvature / (1.0 + std::sqrt(std::max(0.0, 1.0 - h * h * curvature * curvature)));
}

// An edge from `front` (z >= 0) to `back` (z < 0). The rasterizer, like gl_ClipDistance, cuts the
// drawn chord where z, interpolated along it, is 0: at the fraction t = front.z / (front.z - back.z)
// of the chord, while the true image ends on the rim at the edge's own point at t. The drawn piece
// lies within that offset of the chord of the true piece, which lies within its sagitta of the arc.
double crossing_error(const glm::dvec3& front, const glm::dvec3& back) {
    const double t = front.z / (front.z - back.z);
    const glm::dvec3 rim = front + t * (back - front);
    const glm::dvec3 back_direction = glm::normalize(back);
    if (!(1.0 + back_direction.z > kSingular)) return INFINITY;  // the drawn chord runs off to infinity
    if (rim == glm::dvec3(0.0)) return 0.0;                      // the edge passes through the centre
    const glm::dvec2 drawn_cut = glm::mix(disc_at(front), disc_of(back_direction), t);
    return arc_sagitta(front, rim) + glm::distance(drawn_cut, disc_at(rim));
}

// In (u, v) units: the disc's diameter, 2 disc units, spans the tile's side, 1.
double uv_sagitta(const ShadowMap& map, const glm::dvec3& a, const glm::dvec3& b) {
    return edge_sagitta(map.paraboloid, a, b) / 2.0;
}

// A central difference sized by the distance to the centre.
glm::dvec2 uv_derivative(const ShadowMap& map, const glm::dvec3& p, const glm::dvec3& direction) {
    const double step = 1e-6 * glm::length(p - map.paraboloid.centre);
    return (glm::dvec2(uvz_of(map, p + step * direction)) - glm::dvec2(uvz_of(map, p - step * direction))) /
           (2.0 * step);
}

// d = (|q| - near) / (far - near)
double depth_slope(const ShadowMap& map, const glm::dvec3& l, const glm::dvec3& p) {
    const Paraboloid& pb = map.paraboloid;
    return glm::dot(glm::normalize(in_frame(pb, p)), pb.frame_from_world * l) / (pb.far - pb.near);
}

// Back along a radial ray, d falls by 1 / (far - near) per unit.
double distance_back_to_depth(const ShadowMap& map, const glm::dvec3& l, const glm::dvec3& p, double depth) {
    return (uvz_of(map, p).z - depth) * (map.paraboloid.far - map.paraboloid.near);
}

// s = 1 − (|q| − near) / (far − near) = (|q| − far) / (near − far): near and far swapped.
ShadowMap reversed_depth(const ShadowMap& map) {
    ShadowMap reversed = map;
    std::swap(reversed.paraboloid.near, reversed.paraboloid.far);
    return reversed;
}

std::vector<NamedValue> parameters(const ShadowMap& map) {
    const Paraboloid& p = map.paraboloid;
    return {
        {"centre", p.centre}, {"frame_from_world", glm::dmat4(p.frame_from_world)}, {"near", p.near}, {"far", p.far}};
}

}  // namespace

constinit const ProjectionKind paraboloid_projection{.name = "paraboloid",
                                                     .homogeneous = homogeneous,
                                                     .world_of = world_of,
                                                     .reversed_depth = reversed_depth,
                                                     .clip_distance = clip_distance,
                                                     .edge_sagitta = uv_sagitta,
                                                     .fills_disc = true,
                                                     .uv_derivative = uv_derivative,
                                                     .depth_slope = depth_slope,
                                                     .distance_back_to_depth = distance_back_to_depth,
                                                     .parameters = parameters,
                                                     .parameters_key = "paraboloid",
                                                     .glsl = "paraboloid_projection",
                                                     .glsl_prefix = "shadowParaboloid"};

glm::dvec2 disc_of(const glm::dvec3& direction) { return glm::dvec2(direction) / (1.0 + direction.z); }

glm::dvec3 direction_of(const glm::dvec2& disc) {
    const double rho2 = glm::dot(disc, disc);
    return glm::dvec3(2.0 * disc, 1.0 - rho2) / (1.0 + rho2);
}

double edge_sagitta(const Paraboloid& paraboloid, const glm::dvec3& a, const glm::dvec3& b) {
    if (lexicographically_less(b, a)) return edge_sagitta(paraboloid, b, a);  // one order: the same bits
    const glm::dvec3 qa = in_frame(paraboloid, a), qb = in_frame(paraboloid, b);
    if (qa == glm::dvec3(0.0) || qb == glm::dvec3(0.0)) return 0.0;  // an end at the centre has no image
    const bool a_in_front = qa.z >= 0.0, b_in_front = qb.z >= 0.0;   // as the clip distance >= 0 keeps them
    if (a_in_front && b_in_front) return arc_sagitta(qa, qb);
    if (a_in_front) return crossing_error(qa, qb);
    if (b_in_front) return crossing_error(qb, qa);
    return 0.0;  // behind the plane: clipped away, nothing drawn
}

}  // namespace shadowlab
