// Splitting a caster mesh until its straight edges follow the curved images its map's kind draws
// of them: each edge is halved by its own sagitta, so the triangles on either side agree on it.
#include "raster/paraboloid_edges.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "maps/map_lookup.hpp"
#include "maps/projection_kind.hpp"

namespace shadowlab {
namespace {

// Levels of splitting at most. Halving an edge divides its sagitta by about 4 (a shallow arc's
// sagitta grows with the square of its chord), and no sagitta in the disc exceeds 1 disc unit, R / 2
// texels for a tile R texels wide: 8 levels bring any edge in front of the plane under half a texel
// for tiles up to 65536 texels (R / 2 / 4^8 <= 1/2), while a triangle yields at most 4^8 pieces. An
// edge crossing the plane near the map's singular point keeps a large error until its crossing piece
// is short; the limit ends that too.
constexpr int kMaxSplitDepth = 8;

// The split of one map: its kind's sagitta, resolved once, and the target in units of the map's (u, v).
struct SplitRule {
    const ShadowMap& map;
    double (*sagitta)(const ShadowMap&, const glm::dvec3&, const glm::dvec3&);
    double max_sagitta;
};

// The rule for a map at a texture resolution; refused unless the kind bends edges and the target and
// the tile are > 0 (a target of 0 would split every bowed edge down to the depth limit).
SplitRule split_rule(const ShadowMap& map, int texture_resolution) {
    const ProjectionKind& kind = projection_kind(map);
    const double texels_per_unit = tile_resolution(map, texture_resolution);  // the tile spans (u, v) in [0, 1]
    if (!kind.edge_sagitta || !(map.max_sagitta_texels > 0.0) || !(texels_per_unit > 0.0))
        throw std::invalid_argument(std::string("caster splitting: a ") + kind.name +
                                    " map must bend edges and have max_sagitta_texels > 0 and a tile");
    return {.map = map, .sagitta = kind.edge_sagitta, .max_sagitta = map.max_sagitta_texels / texels_per_unit};
}

// Whether an edge born `depth` levels down is halved: the one rule for triangles and lone edges alike.
bool halves(const SplitRule& rule, const glm::dvec3& a, const glm::dvec3& b, int depth) {
    return depth < kMaxSplitDepth && rule.sagitta(rule.map, a, b) > rule.max_sagitta;
}

// The points after a along a–b, b last, as split from `depth` levels down. Edges are halved at their
// world midpoint. Halving the angle instead (the point whose direction bisects it) leaves fewer
// pieces, 7 % fewer in the lamp room, but coarser far from the light, where the depth, interpolated
// linearly across the disc, strays most: 2.4 to 3.3 times the texels off by a hundredth of the range.
void append_split(const SplitRule& rule, const glm::dvec3& a, const glm::dvec3& b, int depth,
                  std::vector<glm::dvec3>& points) {
    if (halves(rule, a, b, depth)) {
        const glm::dvec3 middle = (a + b) / 2.0;
        append_split(rule, a, middle, depth + 1, points);
        append_split(rule, middle, b, depth + 1, points);
    } else
        points.push_back(b);
}

// Splits triangles into one mesh: the input's vertices, then one midpoint per split edge. Crack-free
// with the depth limit too: an edge that is halved is born at the same depth in both triangles holding
// it (the halves of a halved edge one level down on either side; an inner edge between two pieces of
// one triangle), so the limit stops it on both sides alike; an edge left whole is never halved later.
class Splitter {
public:
    Splitter(const WorldTriangles& source, const SplitRule& rule) : source_(source), rule_(rule) {
        out_.vertices = source.vertices;
    }

    // Edge k of a triangle runs from its vertex k to vertex k + 1. The triangle is turned so that its
    // split edges come first, then cut into 2 (one split edge: midpoint to the opposite corner), 3 (two:
    // a corner triangle and the rest of the quad along its shorter diagonal) or 4 pieces (three:
    // midpoint subdivision), each split again one level deeper. Each piece keeps the object and the
    // alpha test of the source triangle it was cut from.
    void split(const std::array<int, 3>& t, int source, int depth) {
        std::array<bool, 3> halved;
        for (int k = 0; k < 3; ++k) halved[k] = halves(rule_, vertex(t[k]), vertex(t[(k + 1) % 3]), depth);
        const int count = int(std::count(halved.begin(), halved.end(), true));
        if (count == 0) {
            out_.triangles.push_back(t);
            out_.object.push_back(source_.object[source]);
            if (source_.alpha_tested()) out_.alpha.push_back(piece_alpha(t, source));
            return;
        }
        int first = 0;  // the split edge after an unsplit one (with three split edges, any)
        for (int k = 0; k < 3; ++k)
            if (halved[k] && !halved[(k + 2) % 3]) first = k;
        const int a = t[first], b = t[(first + 1) % 3], c = t[(first + 2) % 3];
        const auto deeper = [&](int p, int q, int r) { split({p, q, r}, source, depth + 1); };
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

    // The source triangle's alpha test with the piece's corners' texture coordinates: each corner's
    // barycentric weights in the source triangle (a piece's corners lie in its plane).
    TriangleAlpha piece_alpha(const std::array<int, 3>& piece, int source) const {
        TriangleAlpha alpha = source_.alpha[source];
        if (!alpha.test) return alpha;
        const std::array<int, 3>& s = source_.triangles[source];
        const glm::dvec3 a = vertex(s[0]), ab = vertex(s[1]) - a, ac = vertex(s[2]) - a;
        const double ab_ab = glm::dot(ab, ab), ab_ac = glm::dot(ab, ac), ac_ac = glm::dot(ac, ac);
        const double determinant = ab_ab * ac_ac - ab_ac * ab_ac;  // > 0: a caster has an area
        const TriangleAlpha whole = alpha;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 p = vertex(piece[k]) - a;
            const double p_ab = glm::dot(p, ab), p_ac = glm::dot(p, ac);
            alpha.uv[k] =
                whole.uv_at((ac_ac * p_ab - ab_ac * p_ac) / determinant, (ab_ab * p_ac - ab_ac * p_ab) / determinant);
        }
        return alpha;
    }
    double distance(int i, int j) const { return glm::distance(vertex(i), vertex(j)); }

    // The one midpoint of the edge i–j, whichever triangle asks first ((a + b) / 2 is symmetric).
    int midpoint(int i, int j) {
        const auto key = (std::uint64_t(std::min(i, j)) << 32) | std::uint64_t(std::max(i, j));
        const auto [at, made] = midpoints_.try_emplace(key, int(out_.vertices.size()));
        if (made) out_.vertices.push_back((out_.vertices[i] + out_.vertices[j]) / 2.0);
        return at->second;
    }

    const WorldTriangles& source_;
    SplitRule rule_;
    WorldTriangles out_;
    std::unordered_map<std::uint64_t, int> midpoints_;
};

}  // namespace

double texels_per_disc_unit(const ShadowMap& map, int texture_resolution) {
    return tile_resolution(map, texture_resolution) / 2.0;
}

double edge_sagitta_texels(const ShadowMap& map, const glm::dvec3& a, const glm::dvec3& b, int texture_resolution) {
    const ProjectionKind& kind = projection_kind(map);
    return kind.edge_sagitta ? kind.edge_sagitta(map, a, b) * tile_resolution(map, texture_resolution) : 0.0;
}

bool splits_casters(const ShadowMap& map) { return projection_kind(map).edge_sagitta && map.max_sagitta_texels > 0.0; }

WorldTriangles split_casters(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object,
                             const ShadowMap& map, int texture_resolution) {
    Splitter splitter(triangles, split_rule(map, texture_resolution));
    for (std::size_t i = 0; i < triangles.triangles.size(); ++i)
        if (casts_per_object.at(triangles.object[i])) splitter.split(triangles.triangles[i], int(i), 0);
    return std::move(splitter).result();
}

std::vector<glm::dvec3> split_edge(const ShadowMap& map, const glm::dvec3& a, const glm::dvec3& b,
                                   int texture_resolution) {
    std::vector<glm::dvec3> points{a};
    append_split(split_rule(map, texture_resolution), a, b, 0, points);
    return points;
}

}  // namespace shadowlab
