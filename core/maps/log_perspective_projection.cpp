// The logarithmic perspective map's mapping, inverse, clip plane, derivatives and the sagitta of its
// images of straight edges in closed form. Depth, its slope and reversal are the perspective 4x4's,
// as linear_projection computes them.
#include "maps/log_perspective_projection.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "maps/linear_projection.hpp"

namespace shadowlab {
namespace {

double log_range(const LogWarp& warp) { return std::log(warp.far / warp.near); }
double clip_w(const LogWarp& warp) { return kLogClipShare * warp.near; }

glm::dvec4 perspective(const ShadowMap& map, const glm::dvec3& world) {
    return map.world_to_uvz * glm::dvec4(world, 1.0);
}

// (u w, v w, d_pre, w): the perspective's u and depth rows, v from w.
glm::dvec4 homogeneous(const ShadowMap& map, const glm::dvec3& world) {
    const glm::dvec4 h = perspective(map, world);
    return {h.x, log_warp_v(map.log_warp, h.w) * h.w, h.z, h.w};
}

glm::dvec2 uv_of(const glm::dvec4& h) { return glm::dvec2(h.x, h.y) / h.w; }

// w from v, then the point whose u, depth and w rows give (u w, d w, w): three planes meeting in it.
glm::dvec3 world_of(const ShadowMap& map, const glm::dvec3& uvz) {
    const double w = log_warp_w(map.log_warp, uvz.y);
    const glm::dmat4& m = map.world_to_uvz;
    const auto row = [&](int r) { return glm::dvec3(m[0][r], m[1][r], m[2][r]); };
    const glm::dmat3 rows_as_columns(row(0), row(2), row(3));
    const glm::dvec3 right(uvz.x * w - m[3][0], uvz.z * w - m[3][2], w - m[3][3]);
    return glm::inverse(glm::transpose(rows_as_columns)) * right;
}

// Depth is the perspective's: its reversal, slope and distances are the linear kind's.
ShadowMap reversed_depth(const ShadowMap& map) { return linear_projection.reversed_depth(map); }
double depth_slope(const ShadowMap& map, const glm::dvec3& l, const glm::dvec3& p) {
    return linear_projection.depth_slope(map, l, p);
}
double distance_back_to_depth(const ShadowMap& map, const glm::dvec3& l, const glm::dvec3& p, double depth) {
    return linear_projection.distance_back_to_depth(map, l, p, depth);
}

// The signed distance to the plane w = near / 2 (>= 0: drawn).
double clip_distance(const ShadowMap& map, const glm::dvec3& world) {
    return perspective(map, world).w - clip_w(map.log_warp);
}

bool lexicographically_less(const glm::dvec3& a, const glm::dvec3& b) {
    return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
}

// The sagitta of the image of a segment whose ends lie on the map's side (w >= near / 2), from their
// perspective images. Along a straight edge h.x and w are affine in its parameter, so u = h.x / w is
// affine in s = 1 / w, u = α + β s, while v = -log(near s) / L, L = log(far / near). The bow from the
// chord, (β / L) [log(r) (s - s_a) - (s_b - s_a) log(s / s_a)] / |chord| with r = s_b / s_a, is
// greatest where the curve runs parallel to the chord, at the logarithmic mean s* = (s_b - s_a) /
// log r: there it is |Δu| |(r - 1) - log r - (r - 1) log((r - 1) / log r)| / (|r - 1| L |chord|).
double front_sagitta(const ShadowMap& map, const glm::dvec4& pa, const glm::dvec4& pb) {
    const double r_minus_1 = (pa.w - pb.w) / pb.w;  // s_b / s_a - 1 = w_a / w_b - 1
    if (!(std::abs(r_minus_1) > 0.0)) return 0.0;   // at one distance: v constant, a straight row
    const double log_r = std::log1p(r_minus_1);
    const double du = pb.x / pb.w - pa.x / pa.w, dv = -log_r / log_range(map.log_warp);
    const double chord = std::hypot(du, dv);
    const double bow = r_minus_1 - log_r - r_minus_1 * std::log(r_minus_1 / log_r);
    return std::abs(du) * std::abs(bow) / (std::abs(r_minus_1) * log_range(map.log_warp) * chord);
}

// An edge from `front` (w >= near / 2) to `back`. The rasterizer, like gl_ClipDistance, cuts the drawn
// chord where the clip distance, interpolated along it, is 0: at the edge's own point c at that fraction
// t, but at the division of the interpolated homogeneous ends, while the true image of c is the kind's
// own. The drawn piece lies within that offset of the chord of the true piece front–c, which lies
// within its sagitta of the curve.
double crossing_error(const ShadowMap& map, const glm::dvec3& front, const glm::dvec3& back) {
    const double side_front = clip_distance(map, front), side_back = clip_distance(map, back);
    const double t = side_front / (side_front - side_back);
    const glm::dvec3 cut = front + t * (back - front);
    const glm::dvec2 drawn_cut = uv_of(glm::mix(homogeneous(map, front), homogeneous(map, back), t));
    return front_sagitta(map, perspective(map, front), perspective(map, cut)) +
           glm::distance(drawn_cut, uv_of(homogeneous(map, cut)));
}

// Symmetric in a and b to the last bit (one order), so that the two triangles sharing an edge agree.
double edge_sagitta(const ShadowMap& map, const glm::dvec3& a, const glm::dvec3& b) {
    if (lexicographically_less(b, a)) return edge_sagitta(map, b, a);
    const bool a_in_front = clip_distance(map, a) >= 0.0, b_in_front = clip_distance(map, b) >= 0.0;
    if (a_in_front && b_in_front) return front_sagitta(map, perspective(map, a), perspective(map, b));
    if (a_in_front) return crossing_error(map, a, b);
    if (b_in_front) return crossing_error(map, b, a);
    return 0.0;  // behind the clip plane: nothing drawn
}

// u by the quotient rule on the rows; v = log(w / near) / L changes by (dw / w) / L.
glm::dvec2 uv_derivative(const ShadowMap& map, const glm::dvec3& p, const glm::dvec3& direction) {
    const glm::dvec4 h = perspective(map, p), dh = map.world_to_uvz * glm::dvec4(direction, 0.0);
    return {(dh.x * h.w - h.x * dh.w) / (h.w * h.w), dh.w / (h.w * log_range(map.log_warp))};
}

std::vector<NamedValue> parameters(const ShadowMap& map) {
    return {{"world_to_uvz", map.world_to_uvz}, {"log_near", map.log_warp.near}, {"log_far", map.log_warp.far}};
}

}  // namespace

constinit const ProjectionKind log_perspective_projection{.name = "log perspective",
                                                          .homogeneous = homogeneous,
                                                          .world_of = world_of,
                                                          .reversed_depth = reversed_depth,
                                                          .clip_distance = clip_distance,
                                                          .edge_sagitta = edge_sagitta,
                                                          .uv_derivative = uv_derivative,
                                                          .depth_slope = depth_slope,
                                                          .distance_back_to_depth = distance_back_to_depth,
                                                          .parameters = parameters,
                                                          .glsl = "log_perspective_projection",
                                                          .glsl_prefix = "shadowLogPerspective"};

double log_warp_v(const LogWarp& warp, double w) {
    return std::log(std::max(w, clip_w(warp)) / warp.near) / log_range(warp);
}

double log_warp_w(const LogWarp& warp, double v) { return warp.near * std::exp(v * log_range(warp)); }

}  // namespace shadowlab
