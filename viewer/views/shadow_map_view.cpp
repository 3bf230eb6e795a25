// The Shadow map view: the depth image the method produces (near dark, far light, empty texels
// white), one screen square per texel, with the camera frustum drawn where the map puts it; a
// texture of several maps (an atlas of cascades) with each tile's border and its label. On a
// paraboloid map, the tessellation error: the edges of the caster that bow most, straight as drawn
// and curved as truly seen, with the worst sagitta in texels. For a filter that reads moments (vsm,
// evsm), the option to paint instead what it reads: the blurred moments' mean, in the depth's greys,
// or their standard deviation on a heat ramp, non-zero where the blur mixes depths (the edges where
// Chebyshev's bound lets light bleed).
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <set>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include "lookup/moment_map.hpp"
#include "maps/map_lookup.hpp"
#include "maps/map_mask.hpp"
#include "maps/projection_kind.hpp"
#include "methods/cascade_atlas.hpp"
#include "raster/paraboloid_edges.hpp"
#include "views/colour_bar.hpp"
#include "views/space_parts.hpp"
#include "views/view_parts.hpp"

namespace shadowlab {
namespace {

// A value per texel of a texture as the view paints it: the depth (as its map's format stored it,
// read back through DepthMap::at) or a moment; NaN where a texel holds no value.
struct TexelValues {
    int resolution = 0;
    std::vector<float> values;  // row-major, y * resolution + x

    float at(int x, int y) const { return values[size_t(y) * resolution + x]; }
};

// The depths read back as d, in float: the grey levels resolve far less.
TexelValues decoded(const DepthMap& depth) {
    TexelValues out{.resolution = depth.resolution, .values = std::vector<float>(depth.codes.size())};
    for (int y = 0; y < depth.resolution; ++y)
        for (int x = 0; x < depth.resolution; ++x) out.values[depth.index(x, y)] = float(depth.at(x, y));
    return out;
}

RgbImage depth_to_grey(const TexelValues& depth) {
    float lo = 1.0f, hi = 0.0f;
    for (float d : depth.values)
        if (d < 1.0f) lo = std::min(lo, d), hi = std::max(hi, d);
    const float span = hi > lo ? hi - lo : 1.0f;
    const int n = depth.resolution;
    RgbImage image(n, n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const float d = depth.at(x, y);  // texel row y = v; the image's row 0 is its top: v = 1
            const double grey = d >= 1.0f ? 255.0 : 30.0 + 190.0 * (d - lo) / span;
            unsigned char* pixel = image.at(x, n - 1 - y);
            pixel[0] = pixel[1] = pixel[2] = static_cast<unsigned char>(grey);
        }
    return image;
}

const glm::dvec3 kBackground{0.12, 0.13, 0.16};

Rgb to_rgb(const glm::dvec3& colour) {
    const glm::dvec3 scaled = glm::round(255.0 * colour);
    return {static_cast<unsigned char>(scaled.r), static_cast<unsigned char>(scaled.g),
            static_cast<unsigned char>(scaled.b)};
}

// The standard deviations on the heat ramp, 0 black to the texture's largest bright; texels holding
// no value (NaN: the cross's empty cells) the background.
RgbImage deviation_to_heat(const TexelValues& deviation, float largest) {
    const int n = deviation.resolution;
    RgbImage image(n, n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const float sigma = deviation.at(x, y);
            const Rgb colour = std::isnan(sigma) ? to_rgb(kBackground) : heat(largest > 0.0f ? sigma / largest : 0.0);
            std::copy(colour.begin(), colour.end(), image.at(x, n - 1 - y));
        }
    return image;
}

float largest_value(const TexelValues& texture) {
    float largest = 0.0f;
    for (float v : texture.values)
        if (!std::isnan(v)) largest = std::max(largest, v);
    return largest;
}

// Per texel of the stored texture, the blurred moments' mean or standard deviation in depth units, as
// the filter's moment encoding reads them back (MomentEncoding::depth_statistics).
TexelValues moment_texture(const Inspection& in, TextureShown shown) {
    const ShadowFilter& filter = in.lookup.filter;
    const MomentEncoding& encoding = filter_of(filter).moments;
    const MomentMap moments = blurred_moments(in.depth(), in.setup, filter);
    TexelValues texture{.resolution = moments.resolution, .values = std::vector<float>(moments.moments.size())};
    for (size_t i = 0; i < moments.moments.size(); ++i) {
        const glm::dvec2 statistics = encoding.depth_statistics(glm::dvec4(moments.moments[i]), filter);
        texture.values[i] = float(shown == TextureShown::moment_mean ? statistics.x : statistics.y);
    }
    return texture;
}

// Texel edges as lines: x = k - 1/2 and y = k - 1/2 in image pixels, just above the image.
Placed texel_grid(int n) {
    std::vector<std::pair<glm::dvec3, glm::dvec3>> lines;
    for (int k = 0; k <= n; ++k) {
        lines.push_back({{k - 0.5, -0.5, 0.5}, {k - 0.5, n - 0.5, 0.5}});
        lines.push_back({{-0.5, k - 0.5, 0.5}, {n - 0.5, k - 0.5, 0.5}});
    }
    return segments_polydata(lines, glm::dmat4(1.0));
}

// Before each render: the grid shows once a texel spans at least 8 screen pixels (zoomed in).
class TexelGridToggle : public vtkCommand {
public:
    static TexelGridToggle* New() { return new TexelGridToggle; }
    vtkSmartPointer<vtkActor> grid;
    void Execute(vtkObject* caller, unsigned long, void*) override {
        auto* renderer = static_cast<vtkRenderer*>(caller);
        const double pixels_per_texel =
            renderer->GetSize()[1] / (2.0 * renderer->GetActiveCamera()->GetParallelScale());
        grid->SetVisibility(pixels_per_texel >= 8.0);
    }
};

// World -> image pixels of the texture for one map: its texel (x, y) is centred at pixel (x, y) of
// the image actor, its tile where the viewport puts it; drawn just above the image.
// The map's tile in texture pixels, around the drawing plane z = 1.
Aabb tile_in_pixels(const ShadowMap& map, int n) {
    return {{map.viewport.x * n - 0.5, map.viewport.y * n - 0.5, 0.5},
            {map.viewport.z * n - 0.5, map.viewport.w * n - 0.5, 1.5}};
}

// The map's mask (maps/map_mask.hpp) as half-spaces of the image's pixels, homogeneous: the
// half-plane a u + b v + c >= 0 with u = (x - x0 w) / width, v = (y - y0 w) / height in its tile.
std::vector<ClipPlane> mask_in_pixels(const ShadowMap& map, int n) {
    const glm::dvec2 origin(map.viewport.x * n - 0.5, map.viewport.y * n - 0.5);
    const glm::dvec2 size((map.viewport.z - map.viewport.x) * n, (map.viewport.w - map.viewport.y) * n);
    std::vector<ClipPlane> cut;
    for (const glm::dvec3& half : map.mask) {
        const glm::dvec2 per_pixel = glm::dvec2(half) / size;
        cut.push_back({.normal = {per_pixel, 0.0, half.z - glm::dot(per_pixel, origin)}, .offset = 0.0});
    }
    return cut;
}

// A point of the map's (u, v) in the image's pixels, on the drawing plane z.
glm::dvec3 uv_in_pixels(const ShadowMap& map, const glm::dvec2& uv, int n, double z) {
    return {texture_uv(map, uv) * double(n) - 0.5, z};
}

glm::dmat4 pixels_from_world(const ShadowMap& map, int n) {
    glm::dmat4 pixels_from_uvz(1.0);
    pixels_from_uvz[0][0] = (map.viewport.z - map.viewport.x) * n;
    pixels_from_uvz[1][1] = (map.viewport.w - map.viewport.y) * n;
    pixels_from_uvz[2][2] = 0.0;
    pixels_from_uvz[3] = glm::dvec4(map.viewport.x * n - 0.5, map.viewport.y * n - 0.5, 1.0, 1.0);
    return pixels_from_uvz * map.world_to_uvz;
}

// A paraboloid's disc (ρ = 1, where the hemispheres meet: the seam), inscribed in its tile.
void add_disc_rim(const Aabb& tile, std::vector<std::pair<glm::dvec3, glm::dvec3>>& edges) {
    const glm::dvec3 centre{tile.center().x, tile.center().y, 0.6};
    const double radius = (tile.max.x - tile.min.x) / 2;
    constexpr int kSegments = 128;
    const auto at = [&](int k) {
        const double t = 2 * std::numbers::pi * k / kSegments;
        return centre + radius * glm::dvec3(std::cos(t), std::sin(t), 0.0);
    };
    for (int k = 0; k < kSegments; ++k) edges.push_back({at(k), at(k + 1)});
}

// Tiles are labelled up to this many; beyond (a virtual map's pages, each a slot of the pool) the
// labels would cover the texture, and the caption says where the names are.
constexpr size_t kMostLabelledTiles = 16;

// A masked map's region of its tile (mask_outline), outlined, and its name at the region's centroid.
void draw_mask(vtkRenderer* renderer, const ShadowSetup& setup, size_t i, int n,
               std::vector<std::pair<glm::dvec3, glm::dvec3>>& edges) {
    const ShadowMap& map = setup.maps[i];
    const std::vector<glm::dvec2> outline = mask_outline(map);
    if (outline.empty()) return;
    glm::dvec2 centroid(0.0);
    for (size_t k = 0; k < outline.size(); ++k) {
        edges.push_back(
            {uv_in_pixels(map, outline[k], n, 0.6), uv_in_pixels(map, outline[(k + 1) % outline.size()], n, 0.6)});
        centroid += outline[k] / double(outline.size());
    }
    add_world_label(renderer, uv_in_pixels(map, centroid, n, 0.6), map_name(setup, i), 14, kTileBorder, {-24, -6});
}

// Each tile's border, its edges through the texel edges the viewport names, and a label inside its
// top-left corner on two lines, so that it fits a small tile: the map's name ("cascade 2", "front",
// "face +x"; map_name) over "1024²"; a paraboloid's disc drawn in its tile; a masked map's region
// instead (maps sharing a tile, each in its mask: a tetrahedron's faces).
void draw_tiles(vtkRenderer* renderer, const ShadowSetup& setup, int n) {
    const bool labelled = setup.maps.size() <= kMostLabelledTiles;
    std::vector<std::pair<glm::dvec3, glm::dvec3>> edges;
    for (size_t i = 0; i < setup.maps.size(); ++i) {
        if (!setup.maps[i].mask.empty()) {
            draw_mask(renderer, setup, i, n, edges);
            continue;
        }
        const Aabb tile = tile_in_pixels(setup.maps[i], n);
        const glm::dvec3 a(tile.min.x, tile.min.y, 0.6), b(tile.max.x, tile.min.y, 0.6), c(tile.max.x, tile.max.y, 0.6),
            d(tile.min.x, tile.max.y, 0.6);
        for (const auto& edge : {std::pair{a, b}, std::pair{b, c}, std::pair{c, d}, std::pair{d, a}})
            edges.push_back(edge);
        const bool disc = projection_kind(setup.maps[i]).fills_disc;
        if (disc) add_disc_rim(tile, edges);
        if (!labelled) continue;
        const auto side = static_cast<int>(std::lround(tile_resolution(setup.maps[i], n)));
        const std::string text = map_name(setup, i) + "\n" + std::to_string(side) + "²";
        if (disc)  // in the corner the disc leaves empty, under the legend
            add_world_label(renderer, a, text, 14, kTileBorder, {6, 6});
        else
            add_world_label(renderer, d, text, 14, kTileBorder, {6, -40});  // inside the tile, below its top edge
    }
    auto borders = actor_for(segments_polydata(edges, glm::dmat4(1.0)), kTileBorder);
    borders->GetProperty()->SetLineWidth(2.0f);
    renderer->AddActor(borders);
}

const glm::dvec3 kChordColour{0.2, 0.85, 1.0}, kArcColour{1.0, 0.35, 0.75};

// A straight world edge seen by a paraboloid map, with its sagitta in texels (raster/paraboloid_edges).
struct SeenEdge {
    glm::dvec3 a, b;
    double sagitta_texels;
};

bool behind(const ShadowMap& map, const glm::dvec3& a, const glm::dvec3& b) {
    return hemisphere_side(map, a) < 0.0 && hemisphere_side(map, b) < 0.0;
}

// The edges a map draws in the place of one: the edge itself, or its pieces on the map's side where
// the map splits.
std::vector<SeenEdge> drawn_pieces(const ShadowMap& map, const SeenEdge& e, int resolution) {
    if (!splits_casters(map)) return {e};
    const std::vector<glm::dvec3> points = split_edge(map, e.a, e.b, resolution);
    std::vector<SeenEdge> pieces;
    for (size_t k = 0; k + 1 < points.size(); ++k)
        if (!behind(map, points[k], points[k + 1]))
            pieces.push_back(
                {points[k], points[k + 1], edge_sagitta_texels(map, points[k], points[k + 1], resolution)});
    return pieces;
}

// Per caster object, its edges (each once) with some part on the map's side of its plane.
std::map<int, std::vector<SeenEdge>> seen_edges_by_object(const Inspection& in, const ShadowMap& map) {
    const WorldTriangles& t = in.triangles;
    std::set<std::pair<int, int>> done;
    std::map<int, std::vector<SeenEdge>> edges;
    for (size_t i = 0; i < t.triangles.size(); ++i) {
        if (!in.casters.at(t.object[i])) continue;
        for (int k = 0; k < 3; ++k) {
            const auto [first, second] = std::minmax(t.triangles[i][k], t.triangles[i][(k + 1) % 3]);
            const glm::dvec3 &a = t.vertices[first], &b = t.vertices[second];
            if (!done.insert({first, second}).second || behind(map, a, b)) continue;
            edges[t.object[i]].push_back({a, b, edge_sagitta_texels(map, a, b, in.resolution)});
        }
    }
    return edges;
}

double worst_sagitta(const std::vector<SeenEdge>& edges) {
    double worst = 0.0;
    for (const SeenEdge& e : edges) worst = std::max(worst, e.sagitta_texels);
    return worst;
}

// The part of the edge on the map's side, as fractions along a -> b.
std::pair<double, double> front_part(const ShadowMap& map, const SeenEdge& e) {
    const double side_a = hemisphere_side(map, e.a), side_b = hemisphere_side(map, e.b);
    if (side_a >= 0.0 && side_b >= 0.0) return {0.0, 1.0};
    const double cut = side_a / (side_a - side_b);
    return side_a >= 0.0 ? std::pair{0.0, cut} : std::pair{cut, 1.0};
}

// Texture pixels (texel (x, y) centred at pixel (x, y)) of a point before the division, just above
// the image.
glm::dvec3 on_image(const ShadowMap& map, const glm::dvec4& h, int n) {
    return glm::dvec3(texture_uv(map, glm::dvec2(h) / h.w) * double(n) - 0.5, 0.7);
}

// The edge as the rasterizer draws it: its ends projected and joined straight, cut where the plane
// distance interpolated along that chord crosses 0 (clip_where in core/raster/depth_map.cpp).
std::pair<glm::dvec3, glm::dvec3> drawn_chord(const ShadowMap& map, const SeenEdge& e, int n) {
    const glm::dvec4 ha = map_homogeneous(map, e.a), hb = map_homogeneous(map, e.b);
    const auto [from, to] = front_part(map, e);
    return {on_image(map, glm::mix(ha, hb, from), n), on_image(map, glm::mix(ha, hb, to), n)};
}

// The edge as the map truly sees it: 32 points along its part in front, each projected.
std::vector<std::pair<glm::dvec3, glm::dvec3>> true_arc(const ShadowMap& map, const SeenEdge& e, int n) {
    constexpr int pieces = 32;
    const auto [from, to] = front_part(map, e);
    const auto at = [&](int k) {
        return on_image(map, map_homogeneous(map, glm::mix(e.a, e.b, from + (to - from) * k / pieces)), n);
    };
    std::vector<std::pair<glm::dvec3, glm::dvec3>> arc;
    for (int k = 0; k < pieces; ++k) arc.push_back({at(k), at(k + 1)});
    return arc;
}

// One paraboloid map's overlay, cut to its tile: the caster whose edges bow most, each edge drawn
// straight as the map draws it (whole, or its pieces where the map splits its casters) and along its
// true arc; and a line naming the caster, its worst sagitta as given and, split, as drawn.
std::string draw_tessellation_error(vtkRenderer* renderer, const Inspection& in, size_t i) {
    const ShadowMap& map = in.setup.maps[i];
    const std::map<int, std::vector<SeenEdge>> edges = seen_edges_by_object(in, map);
    if (edges.empty()) return map_name(in.setup, i) + ": no caster in front of its plane";
    const auto& [object, worst_edges] = *std::max_element(edges.begin(), edges.end(), [](const auto& x, const auto& y) {
        return worst_sagitta(x.second) < worst_sagitta(y.second);
    });
    std::vector<std::pair<glm::dvec3, glm::dvec3>> chords, arcs;
    std::vector<SeenEdge> drawn;
    for (const SeenEdge& e : worst_edges) {
        for (const SeenEdge& piece : drawn_pieces(map, e, in.resolution)) {
            chords.push_back(drawn_chord(map, piece, in.resolution));
            drawn.push_back(piece);
        }
        for (const auto& piece : true_arc(map, e, in.resolution)) arcs.push_back(piece);
    }
    const Placement in_tile{.clip = tile_in_pixels(map, in.resolution)};
    for (const auto& [segments, colour] : {std::pair{chords, kChordColour}, std::pair{arcs, kArcColour}}) {
        auto actor = actor_for(segments_polydata(segments, in_tile), colour);
        actor->GetProperty()->SetLineWidth(2.0f);
        renderer->AddActor(actor);
    }
    const std::string& name = in.scene.objects[object].name;
    const std::string caster = name.empty() ? "object " + std::to_string(object) : name;
    char text[200];
    std::snprintf(text, sizeof text, "%s: %s's edges bow up to %.1f texels", map_name(in.setup, i).c_str(),
                  caster.c_str(), worst_sagitta(worst_edges));
    if (!splits_casters(map)) return text;
    char split[120];
    std::snprintf(split, sizeof split, ", split to %.2g: %.2f", map.max_sagitta_texels, worst_sagitta(drawn));
    return text + std::string(split);
}

// The texture as shown (a value per texel: the depth, or a moment), and the setup whose tiles say
// where each map lies in it.
struct ShownTexture {
    TexelValues texture;
    ShadowSetup setup;
};

// Where each cube face is shown, in cells of a quarter of the shown texture's side (column, row
// from the top): the cube unfolded as a cross, +y above, -x +z +x -z across, -y below.
constexpr std::array<glm::ivec2, 6> kCrossCells{{{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}}};

// A cube's six faces moved from their 3 x 2 atlas into the cross, texel for texel: the shown
// texture is four faces wide (a face keeps its side, rounded to whole texels); the cells no face
// takes hold `empty`.
ShownTexture as_cross(const Inspection& in, const TexelValues& stored_texture, float empty) {
    const int side = static_cast<int>(std::lround(tile_resolution(in.setup.maps.front(), in.resolution)));
    const int shown_n = 4 * side;
    ShownTexture shown{
        .texture = {.resolution = shown_n, .values = std::vector<float>(size_t(shown_n) * shown_n, empty)},
        .setup = in.setup};
    for (ShadowMap& map : shown.setup.maps) {
        const glm::ivec2 cell = kCrossCells[map.cube_face];
        const ShadowMap& stored = in.setup.maps[&map - shown.setup.maps.data()];
        map.viewport = tile_viewport({.column = cell.x, .row = cell.y, .side = 0.25});
        const glm::ivec2 corner{cell.x * side, shown_n - (cell.y + 1) * side};  // texel rows count up (v)
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) {
                const glm::ivec2 texel = texel_of(stored, (glm::dvec2(x, y) + 0.5) / double(side), in.resolution);
                shown.texture.values[size_t(corner.y + y) * shown_n + corner.x + x] =
                    stored_texture.at(texel.x, texel.y);
            }
    }
    return shown;
}

ShownTexture shown_texture(const Inspection& in, const TexelValues& stored_texture, float empty) {
    const bool cube =
        in.setup.maps.size() == 6 && std::all_of(in.setup.maps.begin(), in.setup.maps.end(),
                                                 [](const ShadowMap& m) { return projection_kind(m).numbered_face; });
    if (cube) return as_cross(in, stored_texture, empty);
    return {stored_texture, in.setup};
}

bool any_bends_edges(const ShadowSetup& setup) {
    return std::any_of(setup.maps.begin(), setup.maps.end(),
                       [](const ShadowMap& m) { return !projection_kind(m).projective(); });
}

// What the view paints, and its words for the caption after the method's name (none for the depth).
struct PaintedTexture {
    ShownTexture shown;
    RgbImage image;
    std::string caption;
    bool on_heat_ramp = false;  // whose bright end is yellow: the frustum is drawn in another colour
};

const glm::dvec3 kFrustumOnGrey{1.0, 0.85, 0.1}, kFrustumOnHeat{0.3, 0.8, 1.0};

// The depth, as stored.
PaintedTexture painted_depth(const Inspection& in, std::string caption) {
    ShownTexture shown = shown_texture(in, decoded(in.depth()), 1.0f);
    RgbImage image = depth_to_grey(shown.texture);
    return {std::move(shown), std::move(image), std::move(caption)};
}

// The moments the filter reads, with their colour bar (the deviation) and the caption's words (the
// filter's MomentEncoding: "VSM's mean m₁ of the depth over a 3×3 box").
PaintedTexture painted_moments(vtkRenderer* renderer, const Inspection& in, TextureShown which) {
    const ShadowFilter& filter = in.lookup.filter;
    const MomentEncoding& encoding = filter_of(filter).moments;
    std::string name = filter.kind;
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::toupper(c); });
    const std::string blur =
        " over a " + std::to_string(filter.kernel_size) + "×" + std::to_string(filter.kernel_size) + " box";
    const float empty = which == TextureShown::moment_mean ? 1.0f : std::numeric_limits<float>::quiet_NaN();
    ShownTexture shown = shown_texture(in, moment_texture(in, which), empty);
    if (which == TextureShown::moment_mean) {
        RgbImage image = depth_to_grey(shown.texture);
        return {std::move(shown), std::move(image),
                name + "'s " + encoding.mean_words + blur + " (near dark, far light)"};
    }
    if (encoding.deviation_words.empty()) {  // one moment: no spread to show
        RgbImage image = depth_to_grey(shown.texture);
        return {std::move(shown), std::move(image), name + "'s moments hold no deviation (one moment)"};
    }
    const float largest = largest_value(shown.texture);
    char middle[32], top[32];
    std::snprintf(middle, sizeof middle, "%.2g", largest / 2);
    std::snprintf(top, sizeof top, "%.2g", largest);
    add_colour_bar(renderer, {.ramp = heat,
                              .ticks = {"0", middle, top},
                              .low_side = "one depth\nunder the blur",
                              .high_side = "depths differ:\nlight may bleed",
                              .title = any_bends_edges(in.setup)  // its legend takes the title's row
                                           ? ""
                                           : "standard deviation " + encoding.deviation_words + ", in depth units"});
    RgbImage image = deviation_to_heat(shown.texture, largest);
    return {std::move(shown), std::move(image),
            name + "'s standard deviation " + encoding.deviation_words + " of the depth" + blur, true};
}

PaintedTexture painted_texture(vtkRenderer* renderer, const Inspection& in, TextureShown which) {
    if (which == TextureShown::depth) return painted_depth(in, "");
    if (!in.lookup.filter.reads_moments())
        return painted_depth(in, "depth (filter " + in.lookup.filter.kind + " reads no moments)");
    return painted_moments(renderer, in, which);
}

ViewReport build_shadow_map_view(vtkRenderer* renderer, const Inspection& in, const ViewOptions& options) {
    renderer->SetBackground(kBackground.r, kBackground.g, kBackground.b);
    if (!in.has_map()) {
        add_caption(renderer, in.title() + ": no shadow map (a geometric technique; see the Stencil count view)");
        return {};
    }
    ViewReport report;
    std::string sagittas;  // per paraboloid map: the worst sagitta, for the caption
    const PaintedTexture painted = painted_texture(renderer, in, options.texture);
    const ShownTexture& shown = painted.shown;
    const int n = shown.texture.resolution;
    show_image(renderer, painted.image);
    for (size_t i = 0; i < shown.setup.maps.size(); ++i) {  // the camera frustum where each linear map puts it
        const ShadowMap& map = shown.setup.maps[i];
        if (!projection_kind(map).projective()) {
            report.notes.push_back(std::string("the camera frustum is not drawn on a ") + projection_kind(map).name +
                                   " map (its edges bend)");
            report.notes.push_back(draw_tessellation_error(renderer, in, i));
            sagittas += "\n" + report.notes.back();
            continue;
        }
        // Cut to the map's tile and its mask: what lies outside them is not in the map.
        const Placement in_tile{
            .to_space = pixels_from_world(map, n), .clip = tile_in_pixels(map, n), .cut = mask_in_pixels(map, n)};
        auto frustum = actor_for(geometry_polydata(in.inputs.frustum, in_tile),
                                 painted.on_heat_ramp ? kFrustumOnHeat : kFrustumOnGrey);
        frustum->GetProperty()->SetLineWidth(2.0f);
        renderer->AddActor(frustum);
    }
    if (shown.setup.maps.size() > 1) draw_tiles(renderer, shown.setup, n);
    if (any_bends_edges(in.setup))
        add_legend(renderer, {{kChordColour, "an edge as a GPU draws it (projected ends joined straight)"},
                              {kArcColour, "the same edge as the map sees it (its true arc)"}});
    vtkNew<TexelGridToggle> toggle;
    toggle->grid = actor_for(texel_grid(n), glm::dvec3(0.35, 0.55, 0.85));
    renderer->AddActor(toggle->grid);
    renderer->AddObserver(vtkCommand::StartEvent, toggle);
    const bool masked =
        std::any_of(in.setup.maps.begin(), in.setup.maps.end(), [](const ShadowMap& m) { return !m.mask.empty(); });
    const std::string maps = in.setup.maps.size() > 1
                                 ? ", " + std::to_string(in.setup.maps.size()) +
                                       (masked ? " maps in regions of one texture" : " maps in tiles")
                                 : "";
    const std::string cross =
        n != in.resolution ? " (stored as 3 x 2, shown unfolded as a cross: +y above, -x +z +x -z across, -y below)"
                           : "";
    const std::string words = painted.caption.empty() ? "" : ": " + painted.caption;
    const char* frustum_words = painted.on_heat_ramp ? "camera frustum in blue; " : "camera frustum in yellow; ";
    const bool linear_maps = std::any_of(in.setup.maps.begin(), in.setup.maps.end(),
                                         [](const ShadowMap& m) { return projection_kind(m).projective(); });
    // The depth format named when it is not the default float32 (the images of the default stay as they were).
    std::string title = "Shadow map " + std::to_string(in.resolution) + "²";
    if (const DepthFormat& format = in.depth().format; !(format == DepthFormat{}))
        title.append(" ").append(describe(format));  // (GCC 12 warns falsely of " " + a string here)
    add_caption(renderer, title + " — " + in.name() + words + maps + cross + " (" + (linear_maps ? frustum_words : "") +
                              (in.setup.maps.size() > kMostLabelledTiles
                                   ? "tile borders in green, too many to label: the Page table view names pages; "
                               : masked                   ? "each map's region of the texture (its mask) in green; "
                               : in.setup.maps.size() > 1 ? "tile borders in green; "
                                                          : "") +
                              "texel grid when zoomed in)" + sagittas);
    return report;
}

}  // namespace

const glm::dvec3 kTileBorder{0.2, 0.9, 0.5};

View shadow_map_view() {
    return {.name = "shadowmap",
            .title = "Shadow map",
            .prepare =
                [](const Inspection& in, const ViewOptions&) {
                    if (in.has_map()) in.depth();
                },
            .build = build_shadow_map_view,
            .choosers = {.texture = true},
            .interaction = {.drag = ViewDrag::pans_image}};
}

}  // namespace shadowlab
