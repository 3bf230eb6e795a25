// The sagitta in closed form: a straight edge and the map's centre span a plane through the centre,
// whose great circle the paraboloid (a stereographic projection from the back pole) maps to a circle
// of the disc; the edge's image is an arc of it. Exact, where sampling points along the edge would
// only approach the arc's farthest point from below; the test samples the edge finely and finds the
// same value.
#include "raster/paraboloid_edges.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "maps/map_lookup.hpp"

namespace shadowlab {
namespace {

// Levels of splitting at most. Halving an edge divides its sagitta by about 4 (a shallow arc's
// sagitta grows with the square of its chord), and no sagitta in the disc exceeds 1 disc unit, R / 2
// texels for a tile R texels wide: 8 levels bring any edge in front of the plane under half a texel
// for tiles up to 65536 texels (R / 2 / 4^8 <= 1/2), while a triangle yields at most 4^8 pieces. An
// edge crossing the plane near the map's singular point keeps a large error until its crossing piece
// is short; the limit ends that too.
constexpr int kMaxSplitDepth = 8;

// 1 + d.z at or below this: the back pole, where the disc coordinates leave every bound (the lookup's
// own threshold, maps/map_lookup.cpp).
constexpr double kSingular = 1e-12;

glm::dvec3 in_frame(const Paraboloid& p, const glm::dvec3& world) { return p.frame_from_world * (world - p.centre); }

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

// Whether an edge born `depth` levels down is halved: the one rule for triangles and lone edges alike.
bool halves(const Paraboloid& paraboloid, const glm::dvec3& a, const glm::dvec3& b, int depth, double max_sagitta) {
    return depth < kMaxSplitDepth && edge_sagitta(paraboloid, a, b) > max_sagitta;
}

// The disc units of a target in texels; refused unless both are > 0 (a target of 0 would split every
// bowed edge down to the depth limit).
double target_in_disc_units(double texels_per_unit, double max_sagitta_texels) {
    if (!(max_sagitta_texels > 0.0) || !(texels_per_unit > 0.0))
        throw std::invalid_argument(
            "paraboloid splitting: the target sagitta and the texels per disc unit must be > 0");
    return max_sagitta_texels / texels_per_unit;
}

// The points after a along a–b, b last, as split from `depth` levels down. Edges are halved at their
// world midpoint. Halving the angle instead (the point whose direction bisects it) leaves fewer
// pieces, 7 % fewer in the lamp room, but coarser far from the light, where the depth, interpolated
// linearly across the disc, strays most: 2.4 to 3.3 times the texels off by a hundredth of the range.
void append_split(const Paraboloid& paraboloid, const glm::dvec3& a, const glm::dvec3& b, int depth, double max_sagitta,
                  std::vector<glm::dvec3>& points) {
    if (halves(paraboloid, a, b, depth, max_sagitta)) {
        const glm::dvec3 middle = (a + b) / 2.0;
        append_split(paraboloid, a, middle, depth + 1, max_sagitta, points);
        append_split(paraboloid, middle, b, depth + 1, max_sagitta, points);
    } else
        points.push_back(b);
}

// Splits triangles into one mesh: the input's vertices, then one midpoint per split edge. Crack-free
// with the depth limit too: an edge that is halved is born at the same depth in both triangles holding
// it (the halves of a halved edge one level down on either side; an inner edge between two pieces of
// one triangle), so the limit stops it on both sides alike; an edge left whole is never halved later.
class Splitter {
public:
    Splitter(const std::vector<glm::dvec3>& vertices, const Paraboloid& paraboloid, double max_sagitta)
        : paraboloid_(paraboloid), max_sagitta_(max_sagitta) {
        out_.vertices = vertices;
    }

    // Edge k of a triangle runs from its vertex k to vertex k + 1. The triangle is turned so that its
    // split edges come first, then cut into 2 (one split edge: midpoint to the opposite corner), 3 (two:
    // a corner triangle and the rest of the quad along its shorter diagonal) or 4 pieces (three:
    // midpoint subdivision), each split again one level deeper.
    void split(const std::array<int, 3>& t, int object, int depth) {
        std::array<bool, 3> halved;
        for (int k = 0; k < 3; ++k)
            halved[k] = halves(paraboloid_, vertex(t[k]), vertex(t[(k + 1) % 3]), depth, max_sagitta_);
        const int count = int(std::count(halved.begin(), halved.end(), true));
        if (count == 0) {
            out_.triangles.push_back(t);
            out_.object.push_back(object);
            return;
        }
        int first = 0;  // the split edge after an unsplit one (with three split edges, any)
        for (int k = 0; k < 3; ++k)
            if (halved[k] && !halved[(k + 2) % 3]) first = k;
        const int a = t[first], b = t[(first + 1) % 3], c = t[(first + 2) % 3];
        const auto deeper = [&](int p, int q, int r) { split({p, q, r}, object, depth + 1); };
        const int ab = midpoint(a, b);
        if (count == 1) {
            deeper(a, ab, c);
            deeper(ab, b, c);
            return;
        }
        const int bc = midpoint(b, c);
        if (count == 2) {
            deeper(ab, b, bc);
            if (distance(a, bc) <= distance(ab, c)) {
                deeper(a, ab, bc);
                deeper(a, bc, c);
            } else {
                deeper(a, ab, c);
                deeper(ab, bc, c);
            }
            return;
        }
        const int ca = midpoint(c, a);
        deeper(a, ab, ca);
        deeper(ab, b, bc);
        deeper(ca, bc, c);
        deeper(ab, bc, ca);
    }

    WorldTriangles result() && { return std::move(out_); }

private:
    glm::dvec3 vertex(int i) const { return out_.vertices[i]; }
    double distance(int i, int j) const { return glm::distance(vertex(i), vertex(j)); }

    // The one midpoint of the edge i–j, whichever triangle asks first ((a + b) / 2 is symmetric).
    int midpoint(int i, int j) {
        const auto key = (std::uint64_t(std::min(i, j)) << 32) | std::uint64_t(std::max(i, j));
        const auto [at, made] = midpoints_.try_emplace(key, int(out_.vertices.size()));
        if (made) out_.vertices.push_back((out_.vertices[i] + out_.vertices[j]) / 2.0);
        return at->second;
    }

    const Paraboloid& paraboloid_;
    double max_sagitta_;  // disc units
    WorldTriangles out_;
    std::unordered_map<std::uint64_t, int> midpoints_;
};

}  // namespace

glm::dvec2 disc_of(const glm::dvec3& direction) { return glm::dvec2(direction) / (1.0 + direction.z); }

glm::dvec3 direction_of(const glm::dvec2& disc) {
    const double rho2 = glm::dot(disc, disc);
    return glm::dvec3(2.0 * disc, 1.0 - rho2) / (1.0 + rho2);
}

double texels_per_disc_unit(const ShadowMap& map, int texture_resolution) {
    return tile_resolution(map, texture_resolution) / 2.0;
}

double edge_sagitta(const Paraboloid& paraboloid, const glm::dvec3& a, const glm::dvec3& b) {
    if (lexicographically_less(b, a)) return edge_sagitta(paraboloid, b, a);  // one order: the same bits
    const glm::dvec3 qa = in_frame(paraboloid, a), qb = in_frame(paraboloid, b);
    if (qa == glm::dvec3(0.0) || qb == glm::dvec3(0.0)) return 0.0;  // an end at the centre has no image
    const bool a_in_front = qa.z >= 0.0, b_in_front = qb.z >= 0.0;   // as hemisphere_side >= 0 keeps them
    if (a_in_front && b_in_front) return arc_sagitta(qa, qb);
    if (a_in_front) return crossing_error(qa, qb);
    if (b_in_front) return crossing_error(qb, qa);
    return 0.0;  // behind the plane: clipped away, nothing drawn
}

WorldTriangles split_for_paraboloid(const WorldTriangles& triangles, const Paraboloid& paraboloid,
                                    double texels_per_unit, double max_sagitta_texels) {
    Splitter splitter(triangles.vertices, paraboloid, target_in_disc_units(texels_per_unit, max_sagitta_texels));
    for (std::size_t i = 0; i < triangles.triangles.size(); ++i)
        splitter.split(triangles.triangles[i], triangles.object[i], 0);
    return std::move(splitter).result();
}

std::vector<glm::dvec3> split_edge(const Paraboloid& paraboloid, const glm::dvec3& a, const glm::dvec3& b,
                                   double texels_per_unit, double max_sagitta_texels) {
    std::vector<glm::dvec3> points{a};
    append_split(paraboloid, a, b, 0, target_in_disc_units(texels_per_unit, max_sagitta_texels), points);
    return points;
}

bool splits_casters(const ShadowMap& map) {
    return map.projection == Projection::paraboloid && map.max_sagitta_texels > 0.0;
}

WorldTriangles split_casters(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object,
                             const ShadowMap& map, int texture_resolution) {
    WorldTriangles casters{.vertices = triangles.vertices};
    for (std::size_t i = 0; i < triangles.triangles.size(); ++i)
        if (casts_per_object.at(triangles.object[i])) {
            casters.triangles.push_back(triangles.triangles[i]);
            casters.object.push_back(triangles.object[i]);
        }
    return split_for_paraboloid(casters, map.paraboloid, texels_per_disc_unit(map, texture_resolution),
                                map.max_sagitta_texels);
}

}  // namespace shadowlab
