// Triangles are clipped in homogeneous space, divided by w, and filled row by row at texel centres:
// each row's run of covered texels comes from the edge functions, and the depth is the plane through
// the divided vertices (d / w is affine in (u / w, v / w), so screen-space interpolation of it is exact,
// and so of a reversed format's s = (w − d_pre) / w); each texel keeps its format's code.
#include "raster/depth_map.hpp"

#include "geometry/homogeneous_clip.hpp"
#include "math/parallel_rows.hpp"
#include "maps/map_lookup.hpp"
#include "maps/map_mask.hpp"
#include "maps/projection_kind.hpp"
#include "raster/paraboloid_edges.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace shadowlab {
namespace {

constexpr double kMinRelativeW = 1e-9;  // clipped w stays above this fraction of the triangle's largest |w|

using Polygon = HomogeneousPolygon;  // (u, v, d_pre, w)

// ---- Clipping: the part of a caster on the map ----

// The half-spaces of the map: w > 0 and 0 <= u, v <= w, in front of the map's centre and on it. The
// w plane sits a hair above 0, relative to the polygon's scale, so the division stays finite.
std::array<ClipPlane, 5> map_planes(double min_w) {
    return {
        {{{0, 0, 0, 1}, min_w}, {{1, 0, 0, 0}, 0.0}, {{-1, 0, 0, 1}, 0.0}, {{0, 1, 0, 0}, 0.0}, {{0, -1, 0, 1}, 0.0}}};
}

// Calls `each` with the map's half-spaces and then its mask's (maps/map_mask.hpp), until it returns false.
template <class Each>
void for_each_plane(double min_w, const std::vector<ClipPlane>& mask, Each&& each) {
    for (const ClipPlane& plane : map_planes(min_w))
        if (!each(plane)) return;
    for (const ClipPlane& plane : mask)
        if (!each(plane)) return;
}

template <class Vertices>
double min_w_of(const Vertices& vertices) {
    double largest_w = 0.0;
    for (const glm::dvec4& h : vertices) largest_w = std::max(largest_w, std::abs(h.w));
    return kMinRelativeW * largest_w;
}

Polygon clip_to_map(Polygon polygon, const std::vector<ClipPlane>& mask) {
    const double min_w = min_w_of(polygon);
    if (!(min_w > 0.0)) return {};
    for_each_plane(min_w, mask, [&](const ClipPlane& plane) {
        polygon = clip(polygon, plane);
        return true;
    });
    return polygon;
}

// What clip_to_map does to a triangle: keeps it whole (every vertex inside every half-space), removes
// it (all three outside one), or cuts it. Decided with the distances clip() computes, so that the two
// quick answers are exactly what clipping would give, without making a polygon.
enum class Clipping { keeps, removes, cuts };

Clipping clipping_of(const std::array<glm::dvec4, 3>& triangle, const std::vector<ClipPlane>& mask) {
    const double min_w = min_w_of(triangle);
    if (!(min_w > 0.0)) return Clipping::removes;
    bool whole = true, removed = false;
    for_each_plane(min_w, mask, [&](const ClipPlane& plane) {
        int outside = 0;
        for (const glm::dvec4& h : triangle) outside += !(glm::dot(plane.normal, h) - plane.offset >= 0.0);
        removed = outside == 3;
        whole = whole && outside == 0;
        return !removed;
    });
    if (removed) return Clipping::removes;
    return whole ? Clipping::keeps : Clipping::cuts;
}

// Every vertex under the map, projected once for all the triangles that share it: homogeneous
// (u, v, d_pre, w) and its kind's clip distance (1 for a kind that clips at no plane); and the map's
// mask as clip planes. The kind is resolved once for the map.
struct MapVertices {
    std::vector<glm::dvec4> homogeneous;
    std::vector<double> side;
    std::vector<ClipPlane> mask;
};

MapVertices map_vertices(const std::vector<glm::dvec3>& world, const ShadowMap& map) {
    const ProjectionKind& kind = projection_kind(map);
    MapVertices out{.homogeneous = std::vector<glm::dvec4>(world.size()),
                    .side = std::vector<double>(world.size(), 1.0),
                    .mask = mask_clip_planes(map)};
    for (std::size_t i = 0; i < world.size(); ++i) out.homogeneous[i] = kind.homogeneous(map, world[i]);
    if (kind.clip_distance)
        for (std::size_t i = 0; i < world.size(); ++i) out.side[i] = kind.clip_distance(map, world[i]);
    return out;
}

// ---- Division: screen triangles ----

// A vertex after division: position in texels of the texture, depth in map units.
struct ScreenVertex {
    glm::dvec2 p;
    double depth;
};

using ScreenTriangle = std::array<ScreenVertex, 3>;

ScreenVertex to_screen(const glm::dvec4& h, const ShadowMap& map, int resolution) {
    return {texture_uv(map, glm::dvec2(h.x, h.y) / h.w) * static_cast<double>(resolution), h.z / h.w};
}

// Appends the part of one caster triangle on the map, as a fan of screen triangles. A kind with a clip
// distance (a paraboloid's hemisphere plane) first cuts it where that distance, interpolated along the
// projected edges, crosses 0 (as gl_ClipDistance does). Most triangles are wholly on the map or wholly off it
// and pass without a polygon.
void add_on_map(const std::array<int, 3>& corners, const MapVertices& vertices, const ShadowMap& map, int resolution,
                std::vector<ScreenTriangle>& out) {
    std::array<glm::dvec4, 3> triangle;
    std::array<double, 3> side;
    int behind = 0;
    for (int k = 0; k < 3; ++k) {
        triangle[k] = vertices.homogeneous[corners[k]];
        side[k] = vertices.side[corners[k]];
        behind += !(side[k] >= 0.0);
    }
    if (behind == 3) return;
    const Clipping clipping = behind == 0 ? clipping_of(triangle, vertices.mask) : Clipping::cuts;
    if (clipping == Clipping::removes) return;
    if (clipping == Clipping::keeps) {
        out.push_back({to_screen(triangle[0], map, resolution), to_screen(triangle[1], map, resolution),
                       to_screen(triangle[2], map, resolution)});
        return;
    }
    const Polygon on_hemisphere =
        clip_where(Polygon(triangle.begin(), triangle.end()), [&](std::size_t i) { return side[i]; });
    std::vector<ScreenVertex> screen;
    for (const glm::dvec4& h : clip_to_map(on_hemisphere, vertices.mask))
        screen.push_back(to_screen(h, map, resolution));
    for (std::size_t k = 1; k + 1 < screen.size(); ++k) out.push_back({screen[0], screen[k], screen[k + 1]});
}

// ---- Filling: texel centres covered, row by row ----

// The texels of one map's tile: first and last column and row.
struct TexelRange {
    glm::ivec2 first, last;
};

TexelRange tile_texels(const ShadowMap& map, int resolution) {
    return {texel_of(map, glm::dvec2(0.0), resolution), texel_of(map, glm::dvec2(1.0), resolution)};
}

// Runs of texels [first, last] (empty when last < first).
struct Run {
    int first, last;
};

Run intersection(const Run& a, const Run& b) { return {std::max(a.first, b.first), std::min(a.last, b.last)}; }

// First and last texel whose centre (i + 0.5) lies in [lo, hi], within `within`.
Run texels_between(double lo, double hi, const Run& within) {
    return intersection({static_cast<int>(std::ceil(lo - 0.5)), static_cast<int>(std::floor(hi - 0.5))}, within);
}

// A guess at a texel index, as an int within [first, last] (NaN gives first); the caller's walk settles it.
int texel_near(double x, int first, int last) { return x >= first ? (x <= last ? static_cast<int>(x) : last) : first; }

bool lexicographically_less(const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

// The directed edge a -> b of a counter-clockwise triangle and the texel centres on its inner side.
class Edge {
public:
    Edge(const glm::dvec2& a, const glm::dvec2& b)
        : reversed_(lexicographically_less(b, a)),
          from_(reversed_ ? b : a),
          along_(reversed_ ? a - b : b - a),
          rise_(a.y - b.y),
          x_per_y_((b.x - a.x) / (b.y - a.y)),
          owns_centres_on_it_(b.y < a.y || (b.y == a.y && b.x < a.x)) {}

    // Twice the signed area of (a, b, p): positive when p lies left of a -> b.
    double at(const glm::dvec2& p) const { return at_x(along_.x * (p.y - from_.y), p.x); }

    // The texels of row y within `row` whose centres the edge holds. Along a row the rounded edge
    // function is monotone in x (every rounded operation is), rising where the edge runs toward lower
    // v: the held texels are the row's end on one side of a crossing. The crossing in exact arithmetic
    // is a guess a rounding (and a truncation) away from it; a step or none either way settles it with
    // the edge function itself, so the run is exactly the centres a test of every texel takes.
    Run held(int y, const Run& row) const {
        const double centre_y = y + 0.5;
        const double along_row = along_.x * (centre_y - from_.y);  // at(p)'s part constant along the row
        const auto holds = [&](int x) {
            const double e = at_x(along_row, x + 0.5);
            return e > 0.0 || (e == 0.0 && owns_centres_on_it_);
        };
        if (rise_ == 0.0) return holds(row.first) ? row : Run{row.first, row.first - 1};
        const double crossing = from_.x + (centre_y - from_.y) * x_per_y_ - 0.5;  // in texel indices
        if (rise_ > 0.0) {                                                        // held from the crossing on
            int x = texel_near(crossing + 1.0, row.first, row.last + 1);
            while (x > row.first && holds(x - 1)) --x;
            while (x <= row.last && !holds(x)) ++x;
            return {x, row.last};
        }
        int x = texel_near(crossing, row.first - 1, row.last);
        while (x < row.last && holds(x + 1)) ++x;
        while (x >= row.first && !holds(x)) --x;
        return {row.first, x};
    }

private:
    // at(p) from its part along_row, constant along p's row. Evaluated from the lexicographically
    // smaller endpoint (`from_`, along `along_`), so that the two triangles sharing an edge get exactly
    // opposite values and no texel centre on it is lost to rounding.
    double at_x(double along_row, double x) const {
        const double e = along_row - along_.y * (x - from_.x);
        return reversed_ ? -e : e;
    }

    bool reversed_;
    glm::dvec2 from_, along_;
    double rise_;     // of the edge function per unit of x
    double x_per_y_;  // the edge's inverse slope, for the guess
    // The top-left rule: a centre exactly on an edge belongs to the one triangle (of the two sharing
    // it, both counter-clockwise) along which the edge runs toward lower v, or along v toward lower u.
    bool owns_centres_on_it_;
};

// The depth over the screen: the plane through the three vertices, d = at_origin + per_x x + per_y y.
struct DepthPlane {
    double at_origin, per_x, per_y;
};

DepthPlane depth_plane(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
    const glm::dvec2 ab = b.p - a.p, ac = c.p - a.p;
    const double ab_depth = b.depth - a.depth, ac_depth = c.depth - a.depth;
    const double determinant = ab.x * ac.y - ab.y * ac.x;  // Cramer's rule for the two slopes
    const double per_x = (ab_depth * ac.y - ac_depth * ab.y) / determinant;
    const double per_y = (ac_depth * ab.x - ab_depth * ac.x) / determinant;
    return {a.depth - per_x * a.p.x - per_y * a.p.y, per_x, per_y};
}

// The nearest depth so far per texel of one row, as the format stores it: the least code, or
// reversed the greatest (codes order as their values, raster/depth_format.hpp). Casters before the
// near plane are stored as d = 0 (code_of clamps).
template <DepthEncoding encoding, bool reversed>
void fill_run(DepthCode* row, const Run& run, const DepthPlane& plane, double centre_y) {
    const double at_row = plane.at_origin + plane.per_y * centre_y;
    for (int x = run.first; x <= run.last; ++x) {
        const DepthCode code = code_of<encoding, reversed>(at_row + plane.per_x * (x + 0.5));
        row[x] = reversed ? std::max(row[x], code) : std::min(row[x], code);
    }
}

// ---- Alpha-tested casters: texture coordinates per texel ----

// An alpha-tested caster's texture coordinates over the texture's texels, perspective-correct as a GPU
// interpolates them (Olano and Greer 1997, as polygon_spans.hpp): a point of the triangle with
// homogeneous weights b has map (u, v, 1) ∝ M b, M's columns the corners' (u w, v w, w), so
// b ∝ M⁻¹ (u, v, 1), and (s, t, q) = U b with U's columns the corners' (u_tex, v_tex, 1) gives the
// coordinates (s, t) / q. From the whole triangle's corners, so that clipping leaves them as they were.
struct TexelUv {
    glm::dmat3 uvq_from_texel;  // U M⁻¹ A, A taking a texel position to the map's (u, v, 1)
    const AlphaTest* test;

    bool keeps(double x, double y) const {
        const glm::dvec3 uvq = uvq_from_texel * glm::dvec3(x, y, 1.0);
        return test->keeps(glm::dvec2(uvq) / uvq.z);
    }
};

// Nullopt when the triangle's plane holds the map's centre (it is seen edge-on: nothing to fill).
std::optional<TexelUv> texel_uv(const std::array<int, 3>& corners, const TriangleAlpha& alpha,
                                const MapVertices& vertices, const ShadowMap& map, int resolution) {
    glm::dmat3 corners_uvw, corners_uvq;
    for (int k = 0; k < 3; ++k) {
        const glm::dvec4& h = vertices.homogeneous[corners[k]];
        corners_uvw[k] = {h.x, h.y, h.w};
        corners_uvq[k] = {alpha.uv[k], 1.0};
    }
    if (glm::determinant(corners_uvw) == 0.0) return std::nullopt;
    // texture_uv(map, uv) * resolution = lo + uv (hi - lo), in texels: taken back.
    const glm::dvec2 lo = texture_uv(map, glm::dvec2(0.0)) * double(resolution);
    const glm::dvec2 span = texture_uv(map, glm::dvec2(1.0)) * double(resolution) - lo;
    const glm::dmat3 map_from_texel{{1.0 / span.x, 0.0, 0.0}, {0.0, 1.0 / span.y, 0.0}, {-lo / span, 1.0}};
    return TexelUv{.uvq_from_texel = corners_uvq * glm::inverse(corners_uvw) * map_from_texel,
                   .test = alpha.test.get()};
}

// fill_run for an alpha-tested caster: a texel whose centre falls where the texture's alpha is below
// the cutoff keeps what it held.
template <DepthEncoding encoding, bool reversed>
void fill_tested_run(DepthCode* row, const Run& run, const DepthPlane& plane, double centre_y, const TexelUv& uv) {
    const double at_row = plane.at_origin + plane.per_y * centre_y;
    for (int x = run.first; x <= run.last; ++x) {
        if (!uv.keeps(x + 0.5, centre_y)) continue;
        const DepthCode code = code_of<encoding, reversed>(at_row + plane.per_x * (x + 0.5));
        row[x] = reversed ? std::max(row[x], code) : std::min(row[x], code);
    }
}

// One row's run filled in the format's codes, chosen once per raster: the loop over texels knows its
// format when it is compiled. The opaque loop tests no alpha: a scene without alpha-tested casters
// draws as before.
struct RunFills {
    void (*opaque)(DepthCode* row, const Run& run, const DepthPlane& plane, double centre_y);
    void (*tested)(DepthCode* row, const Run& run, const DepthPlane& plane, double centre_y, const TexelUv& uv);
};

template <DepthEncoding encoding, bool reversed>
RunFills fills_of() {
    return {fill_run<encoding, reversed>, fill_tested_run<encoding, reversed>};
}

RunFills run_fills(const DepthFormat& format) {
    using E = DepthEncoding;
    const bool r = format.reversed;
    switch (format.encoding) {
        case E::unorm16: return r ? fills_of<E::unorm16, true>() : fills_of<E::unorm16, false>();
        case E::unorm24: return r ? fills_of<E::unorm24, true>() : fills_of<E::unorm24, false>();
        case E::float32: return r ? fills_of<E::float32, true>() : fills_of<E::float32, false>();
    }
    return fills_of<E::float32, false>();
}

// A screen triangle ready to fill: counter-clockwise (both windings are drawn), the texels of its
// bounding box in the tile, and for an alpha-tested caster its texture coordinates (an index into the
// map's TexelUv list).
struct FillTriangle {
    ScreenTriangle corners;
    Run rows, columns;
    int alpha = -1;
};

// Appends the screen triangle, ready to fill, if it has an area and a texel centre in its box in the tile.
void add_to_fill(ScreenTriangle t, const TexelRange& tile, int alpha, std::vector<FillTriangle>& out) {
    const auto& [a, b, c] = t;
    const glm::dvec2 lo = glm::min(a.p, glm::min(b.p, c.p)), hi = glm::max(a.p, glm::max(b.p, c.p));
    const Run rows = texels_between(lo.y, hi.y, {tile.first.y, tile.last.y});
    const Run columns = texels_between(lo.x, hi.x, {tile.first.x, tile.last.x});
    const double area = Edge(a.p, b.p).at(c.p);
    if (rows.last < rows.first || columns.last < columns.first || area == 0.0) return;
    if (area < 0.0) std::swap(t[1], t[2]);
    out.push_back({t, rows, columns, alpha});
}

// The map's caster triangles after clipping and division, ready to fill, and the alpha-tested ones'
// texture coordinates; the cores take them in turn (the least depths do not depend on the order they
// are drawn in).
struct MapFill {
    std::vector<FillTriangle> triangles;
    std::vector<TexelUv> alpha;
};

MapFill fill_triangles(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object, const ShadowMap& map,
                       const TexelRange& tile, int resolution) {
    const MapVertices vertices = map_vertices(triangles.vertices, map);
    std::vector<MapFill> taken(row_threads());
    parallel_rows([&](int first, int stride) {
        std::vector<ScreenTriangle> screen;
        MapFill& mine = taken[first];
        for (std::size_t i = first; i < triangles.triangles.size(); i += stride) {
            if (!casts_per_object.at(triangles.object[i])) continue;
            int alpha = -1;
            if (triangles.alpha_tested() && triangles.alpha[i].test) {
                const std::optional<TexelUv> uv =
                    texel_uv(triangles.triangles[i], triangles.alpha[i], vertices, map, resolution);
                if (!uv) continue;
                alpha = static_cast<int>(mine.alpha.size());
                mine.alpha.push_back(*uv);
            }
            screen.clear();
            add_on_map(triangles.triangles[i], vertices, map, resolution, screen);
            for (const ScreenTriangle& t : screen) add_to_fill(t, tile, alpha, mine.triangles);
        }
    });
    MapFill out;
    for (const MapFill& part : taken) {
        const int offset = static_cast<int>(out.alpha.size());
        for (FillTriangle t : part.triangles) {
            if (t.alpha >= 0) t.alpha += offset;
            out.triangles.push_back(t);
        }
        out.alpha.insert(out.alpha.end(), part.alpha.begin(), part.alpha.end());
    }
    return out;
}

// The tile's rows in bands of kBandRows: a band of a 2048-texel row is 128 KiB, so it stays in a
// core's cache while every triangle that meets it is drawn, instead of each triangle's rows coming
// from memory again.
constexpr int kBandRows = 16;

// The triangles meeting each band, in drawing order, binned once by a counting sort: band b's are
// triangle[start[b]] .. triangle[start[b + 1] - 1].
struct Bands {
    Run tile_rows;
    std::vector<int> start, triangle;

    int count() const { return static_cast<int>(start.size()) - 1; }
    int of_row(int y) const { return (y - tile_rows.first) / kBandRows; }
    Run rows(int band) const {
        const int first = tile_rows.first + band * kBandRows;
        return intersection({first, first + kBandRows - 1}, tile_rows);
    }
    std::span<const int> triangles(int band) const {
        return std::span(triangle).subspan(start[band], start[band + 1] - start[band]);
    }
};

Bands bin_by_band(const std::vector<FillTriangle>& triangles, const Run& tile_rows) {
    Bands bands{.tile_rows = tile_rows};
    bands.start.assign(bands.of_row(tile_rows.last) + 2, 0);
    for (const FillTriangle& t : triangles)
        for (int b = bands.of_row(t.rows.first); b <= bands.of_row(t.rows.last); ++b) ++bands.start[b + 1];
    std::partial_sum(bands.start.begin(), bands.start.end(), bands.start.begin());
    bands.triangle.resize(bands.start.back());
    std::vector<int> next(bands.start.begin(), bands.start.end() - 1);
    for (int i = 0; i < static_cast<int>(triangles.size()); ++i)
        for (int b = bands.of_row(triangles[i].rows.first); b <= bands.of_row(triangles[i].rows.last); ++b)
            bands.triangle[next[b]++] = i;
    return bands;
}

// The triangle's texels in `rows`, each row's run cut from its bounding box by the three edges; an
// alpha-tested caster's texels tested one by one.
void draw_rows(const FillTriangle& triangle, const Run& rows, const RunFills& fills, const std::vector<TexelUv>& alpha,
               DepthMap& map) {
    const auto& [a, b, c] = triangle.corners;
    const Edge edges[] = {{b.p, c.p}, {c.p, a.p}, {a.p, b.p}};
    const DepthPlane plane = depth_plane(a, b, c);
    for (int y = rows.first; y <= rows.last; ++y) {
        Run run = triangle.columns;
        for (const Edge& e : edges) run = intersection(run, e.held(y, run));
        if (triangle.alpha < 0)
            fills.opaque(&map.codes[map.index(0, y)], run, plane, y + 0.5);
        else
            fills.tested(&map.codes[map.index(0, y)], run, plane, y + 0.5, alpha[triangle.alpha]);
    }
}

// The triangles filled on every core, the bands interleaved among them: every texel is written by
// one thread, and its nearest depth does not depend on the order, so the result is the same. A
// reversed format draws the map's reversed depth (s, from the map's own terms), interpolated as d is.
void draw_map(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object, const ShadowMap& map,
              DepthMap& out) {
    const ShadowMap drawn = out.format.reversed ? with_reversed_depth(map) : map;
    const TexelRange tile = tile_texels(drawn, out.resolution);
    const MapFill fill = fill_triangles(triangles, casts_per_object, drawn, tile, out.resolution);
    const Bands bands = bin_by_band(fill.triangles, {tile.first.y, tile.last.y});
    const RunFills fills = run_fills(out.format);
    parallel_rows([&](int first, int stride) {
        for (int b = first; b < bands.count(); b += stride)
            for (int i : bands.triangles(b))
                draw_rows(fill.triangles[i], intersection(bands.rows(b), fill.triangles[i].rows), fills, fill.alpha,
                          out);
    });
}

// Under a page table (a virtual map) each resident page is drawn from the casters that meet it
// rather than from every caster: each level's vertices projected once (orthographic: w = 1), each
// triangle binned to the resident pages its (u, v) box meets, widened by a hair so that a triangle
// on a page's edge reaches both pages (a page's own clipping then cuts it exactly).
std::vector<WorldTriangles> casters_per_page(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object,
                                             const ShadowSetup& setup) {
    const PageTable& table = setup.selection.pages;
    std::vector<std::vector<int>> chosen(setup.maps.size());
    std::vector<bool> level_in_use(table.levels.size(), false);
    for (const PageAddress& a : table.pages) level_in_use[a.level] = true;
    constexpr double kHair = 1e-9;  // of a page
    const int last = table.pages_per_side - 1;
    for (std::size_t level = 0; level < table.levels.size(); ++level) {
        if (!level_in_use[level]) continue;
        std::vector<glm::dvec2> uv(triangles.vertices.size());
        for (std::size_t i = 0; i < uv.size(); ++i)
            uv[i] = glm::dvec2(table.levels[level].world_to_uvz * glm::dvec4(triangles.vertices[i], 1.0)) *
                    double(table.pages_per_side);
        for (std::size_t t = 0; t < triangles.triangles.size(); ++t) {
            if (!casts_per_object.at(triangles.object[t])) continue;
            const auto& [a, b, c] = triangles.triangles[t];
            const glm::dvec2 lo = glm::min(uv[a], glm::min(uv[b], uv[c])) - kHair;
            const glm::dvec2 hi = glm::max(uv[a], glm::max(uv[b], uv[c])) + kHair;
            if (!(hi.x >= 0.0 && hi.y >= 0.0 && lo.x <= table.pages_per_side && lo.y <= table.pages_per_side)) continue;
            const glm::ivec2 first(std::max(0, int(std::floor(lo.x))), std::max(0, int(std::floor(lo.y))));
            const glm::ivec2 final(std::min(last, int(std::floor(hi.x))), std::min(last, int(std::floor(hi.y))));
            for (int y = first.y; y <= final.y; ++y)
                for (int x = first.x; x <= final.x; ++x)
                    if (const int map = table.map_of({.level = int(level), .page = {x, y}}); map >= 0)
                        chosen[map].push_back(int(t));
        }
    }
    std::vector<WorldTriangles> out(setup.maps.size());
    for (std::size_t map = 0; map < chosen.size(); ++map)
        for (int t : chosen[map]) {
            WorldTriangles& page = out[map];
            const int base = static_cast<int>(page.vertices.size());
            for (int k = 0; k < 3; ++k) page.vertices.push_back(triangles.vertices[triangles.triangles[t][k]]);
            page.triangles.push_back({base, base + 1, base + 2});
            page.object.push_back(triangles.object[t]);
            if (triangles.alpha_tested()) page.alpha.push_back(triangles.alpha[t]);
        }
    return out;
}

}  // namespace

DepthMap::DepthMap(int resolution, const DepthFormat& format)
    : resolution(resolution),
      format(format),
      codes(static_cast<std::size_t>(resolution) * resolution, far_code(format)) {}

void DepthMap::set(int x, int y, double depth) { codes[index(x, y)] = depth_code(format, format_value(format, depth)); }

DepthMap rasterize_depth(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object,
                         const ShadowSetup& setup, int resolution, const DepthFormat& format) {
    DepthMap out(resolution, format);
    if (setup.selection.rule == MapSelection::Rule::pages) {
        const std::vector<WorldTriangles> casters = casters_per_page(triangles, casts_per_object, setup);
        for (std::size_t i = 0; i < setup.maps.size(); ++i) draw_map(casters[i], casts_per_object, setup.maps[i], out);
        return out;
    }
    for (const ShadowMap& map : setup.maps) {
        if (splits_casters(map))  // split for this map's curvature and tile: the edges a GPU draws straight
            draw_map(split_casters(triangles, casts_per_object, map, resolution), casts_per_object, map, out);
        else
            draw_map(triangles, casts_per_object, map, out);
    }
    return out;
}

}  // namespace shadowlab
