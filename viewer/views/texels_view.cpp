// The Texels view (seed 003's back-projection): every texel of the map carried back to the surface it
// samples and drawn as its footprint there, over the scene drawn dim and seen from the scene's
// camera: where the pixels are, a user sees how many texels each one gets, and how a warp spends
// them (LiSPSM's texels shrink toward the eye). The map is drawn over every surface, receivers too:
// the stored map holds the casters only, but a receiver's pixel reads the texel whose footprint
// holds it. One map in a checkerboard of two tones so that single texels read; several in a colour each.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include "maps/map_lookup.hpp"
#include "maps/projection_kind.hpp"
#include "raster/depth_map.hpp"
#include "render/map_overlay.hpp"
#include "views/space_parts.hpp"

namespace shadowlab {
namespace {

constexpr size_t kMostQuads = 200'000;  // a 448² map at every texel; llvmpipe still draws it at once

// A colour per map, the Camera view's overlay's (a cascade's maps told apart, the same in both
// views); the checkerboard's darker tone its second.
glm::dvec3 map_colour(int map) { return glm::dvec3(kMapPalette[map % kMapPalette.size()]); }
constexpr double kDarkTone = 0.55;
constexpr double kTowardEye = 0.999;

// A map's tile in texels, [first, end), as texel_of keeps a lookup in it.
struct TileTexels {
    glm::ivec2 first, end;
};

TileTexels tile_texels(const ShadowMap& map, int n) {
    const auto texel = [n](double t) { return static_cast<int>(std::lround(t * n)); };
    return {{texel(map.viewport.x), texel(map.viewport.y)}, {texel(map.viewport.z), texel(map.viewport.w)}};
}

// 1 is the clear value (no caster there); 0 a caster before the near plane, clamped: not where it is.
bool holds_surface(double depth) { return depth > 0.0 && depth < 1.0; }

// The map's (u, v) at a point of the texture given in texels: texture_uv undone.
glm::dvec2 map_uv(const ShadowMap& map, const glm::dvec2& in_texels, int n) {
    const glm::dvec2 lo(map.viewport.x, map.viewport.y), hi(map.viewport.z, map.viewport.w);
    return (in_texels / double(n) - lo) / (hi - lo);
}

// The world point a linear map or a cube face puts at (u, v, d): (u w, v w, d w, w) is world_to_uvz
// of it for some w, so the inverse takes (u, v, d, 1) to the point times 1 / w.
glm::dvec3 unprojected(const glm::dmat4& world_from_uvz, const glm::dvec3& uvz) {
    const glm::dvec4 h = world_from_uvz * glm::dvec4(uvz, 1.0);
    return glm::dvec3(h) / h.w;
}

// A point of the map's unit cube back in the world: a projective map's through its inverse 4x4
// (computed once per map), a kind that bends edges through its own inverse.
glm::dvec3 world_of_uvz(const ShadowMap& map, const glm::dmat4& world_from_uvz, const glm::dvec3& uvz) {
    const ProjectionKind& kind = projection_kind(map);
    return kind.projective() ? unprojected(world_from_uvz, uvz) : kind.world_of(map, uvz);
}

// The depth of the texel `steps` texels along `axis` from `texel`, if it lies in the tile and holds a surface.
std::optional<double> depth_along(const DepthMap& depth, const TileTexels& tile, const glm::ivec2& texel,
                                  const glm::ivec2& axis, int steps) {
    const glm::ivec2 at = texel + steps * axis;
    if (glm::any(glm::lessThan(at, tile.first)) || glm::any(glm::greaterThanEqual(at, tile.end))) return std::nullopt;
    const double d = depth.at(at.x, at.y);
    return holds_surface(d) ? std::optional<double>(d) : std::nullopt;
}

// How the depth changes per texel along `axis` at a texel, on the plane of the surface there: over
// a plane the divided depth is affine in the texture, so three texels in a row that agree on one
// slope lie on it; the triple centred on the texel first, then those ending at it. Where none agrees
// (the texel on an edge, or on a sliver one texel wide) 0: the footprint at the texel's own depth.
double depth_slope(const DepthMap& depth, const TileTexels& tile, const glm::ivec2& texel, const glm::ivec2& axis) {
    for (const int first : {-1, -2, 0}) {
        std::array<std::optional<double>, 3> d;
        for (int k = 0; k < 3; ++k) d[k] = depth_along(depth, tile, texel, axis, first + k);
        if (!d[0] || !d[1] || !d[2]) continue;
        const double before = *d[1] - *d[0], after = *d[2] - *d[1];
        // A few of the format's steps of slack beside a share of the slope (float32: units in the last place)
        const double slack = std::max(4e-7, 4.0 * depth_step(depth.format, *d[1]));
        if (std::abs(after - before) <= 0.05 * std::abs(before + after) + slack) return 0.5 * (before + after);
    }
    return 0.0;
}

// The texel's centre where its depth puts it, and its footprint on the surface there: over a plane the
// divided depth is affine in (u, v), so the corners' depths follow the slopes to the neighbours.
WorldTexel world_texel(const DepthMap& depth, const ShadowMap& map, int index, const glm::dmat4& world_from_uvz,
                       const TileTexels& tile, const glm::ivec2& texel) {
    const double here = depth.at(texel.x, texel.y);
    const glm::dvec2 slope(depth_slope(depth, tile, texel, {1, 0}), depth_slope(depth, tile, texel, {0, 1}));
    const auto at = [&](const glm::dvec2& offset) {  // from the texel's centre, in texels
        const glm::dvec2 uv = map_uv(map, glm::dvec2(texel) + 0.5 + offset, depth.resolution);
        // Kept in the map's depth range: a perspective map's points beyond it may lie behind its eye.
        return world_of_uvz(map, world_from_uvz, glm::dvec3(uv, std::clamp(here + glm::dot(slope, offset), 0.0, 1.0)));
    };
    return {.map = index,
            .texel = texel,
            .centre = at({0.0, 0.0}),
            .corners = {at({-0.5, -0.5}), at({0.5, -0.5}), at({0.5, 0.5}), at({-0.5, 0.5})}};
}

// Calls visit(map, tile, texel) for every `stride`-th texel in u and v of each back-projected tile
// holding a surface.
template <class Visit>
void for_each_surface_texel(const ShadowSetup& setup, const DepthMap& depth, int stride, Visit&& visit) {
    for (size_t i = 0; i < setup.maps.size(); ++i) {
        const TileTexels tile = tile_texels(setup.maps[i], depth.resolution);
        for (int y = tile.first.y; y < tile.end.y; y += stride)
            for (int x = tile.first.x; x < tile.end.x; x += stride)
                if (holds_surface(depth.at(x, y))) visit(static_cast<int>(i), tile, glm::ivec2(x, y));
    }
}

size_t surface_texels(const ShadowSetup& setup, const DepthMap& depth, int stride) {
    size_t count = 0;
    for_each_surface_texel(setup, depth, stride, [&](int, const TileTexels&, const glm::ivec2&) { ++count; });
    return count;
}

}  // namespace

std::vector<WorldTexel> world_texels(const ShadowSetup& setup, const DepthMap& depth, int stride) {
    std::vector<glm::dmat4> world_from_uvz;
    for (const ShadowMap& map : setup.maps) world_from_uvz.push_back(glm::inverse(map.world_to_uvz));
    std::vector<WorldTexel> texels;
    for_each_surface_texel(setup, depth, stride, [&](int map, const TileTexels& tile, const glm::ivec2& texel) {
        const WorldTexel t = world_texel(depth, setup.maps[map], map, world_from_uvz[map], tile, texel);
        if (select_map(setup, t.centre) == map) texels.push_back(t);  // where the map serves: a cascade's own split
    });
    return texels;
}

int texel_stride(const ShadowSetup& setup, const DepthMap& depth, size_t most) {
    // Start where an even spread of the surface texels would fit, and step up while they do not.
    int stride = std::max(1, static_cast<int>(std::sqrt(double(surface_texels(setup, depth, 1)) / double(most))));
    while (surface_texels(setup, depth, stride) > most) ++stride;
    return stride;
}

namespace {

// The texels as quads in camera-relative coordinates (float32 is as fine near the eye as anywhere,
// as in the Camera view), each in its map's colour, alternating tones between grid neighbours. Each
// is drawn a thousandth of its distance nearer the eye, on the same screen spot: in front of the
// surface it lies on, far more than the depth buffer resolves, and behind anything really in front.
Placed texel_quads(const std::vector<WorldTexel>& texels, int stride, const glm::dvec3& origin) {
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> quads;
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetName("colour");
    colours->SetNumberOfComponents(3);
    for (const WorldTexel& t : texels) {
        vtkIdType ids[4];
        for (int k = 0; k < 4; ++k) {
            const glm::dvec3 p = kTowardEye * (t.corners[k] - origin);
            ids[k] = points->InsertNextPoint(p.x, p.y, p.z);
        }
        quads->InsertNextCell(4, ids);
        const bool dark = (t.texel.x / stride + t.texel.y / stride) % 2 == 1;
        const glm::dvec3 c = 255.0 * map_colour(t.map) * (dark ? kDarkTone : 1.0);
        colours->InsertNextTuple3(c.r, c.g, c.b);
    }
    Placed placed{.data = vtkSmartPointer<vtkPolyData>::New()};
    placed.data->SetPoints(points);
    placed.data->SetPolys(quads);
    placed.data->GetCellData()->SetScalars(colours);
    return placed;
}

// The scene, dim, beneath the texels.
void draw_dim_scene(vtkRenderer* renderer, const Inspection& in, const glm::dmat4& local_from_world) {
    std::vector<glm::dvec3> colours = object_colours(in.scene);
    for (glm::dvec3& c : colours) c *= 0.4;
    auto scene = actor_for(
        triangles_polydata(in.triangles, std::vector<bool>(in.scene.objects.size(), true), colours, local_from_world),
        glm::dvec3(1.0));
    scene->GetProperty()->SetAmbient(0.7);  // faces away from the headlight stay legible
    scene->GetProperty()->SetDiffuse(0.5);
    renderer->AddActor(scene);
}

// Texels per screen pixel over those in the picture: their count over the pixels their footprints
// cover, at the renderer's size (hidden texels counted too). nullopt before the renderer has a size.
std::optional<double> texels_per_pixel(const std::vector<WorldTexel>& texels, Camera camera, const int* size) {
    if (!size || size[0] <= 0 || size[1] <= 0) return std::nullopt;
    camera.aspect = static_cast<double>(size[0]) / size[1];  // VTK widens the scene camera's view to the panel
    const glm::dmat4 clip_from_world = camera.projection_matrix() * camera.view_matrix();
    const auto pixel = [&](const glm::dvec3& p) -> std::optional<glm::dvec2> {
        const glm::dvec4 clip = clip_from_world * glm::dvec4(p, 1.0);
        if (!(clip.w > 0.0)) return std::nullopt;
        return (glm::dvec2(clip) / clip.w * 0.5 + 0.5) * glm::dvec2(size[0], size[1]);
    };
    size_t seen = 0;
    double area = 0.0;
    for (const WorldTexel& t : texels) {
        const auto centre = pixel(t.centre);
        if (!centre || centre->x < 0 || centre->y < 0 || centre->x > size[0] || centre->y > size[1]) continue;
        std::array<glm::dvec2, 4> corner;
        bool in_front = true;
        for (int k = 0; k < 4 && in_front; ++k)
            if (const auto c = pixel(t.corners[k]))
                corner[k] = *c;
            else
                in_front = false;
        if (!in_front) continue;
        double twice = 0.0;  // the shoelace formula
        for (int k = 0; k < 4; ++k) twice += corner[k].x * corner[(k + 1) % 4].y - corner[(k + 1) % 4].x * corner[k].y;
        area += 0.5 * std::abs(twice);
        ++seen;
    }
    if (seen == 0 || area <= 0.0) return std::nullopt;
    return seen / area;
}

std::string ordinal(int k) {
    if (k == 1) return "every texel";
    const char* suffix = k % 100 / 10 == 1 ? "th" : k % 10 == 1 ? "st" : k % 10 == 2 ? "nd" : k % 10 == 3 ? "rd" : "th";
    return "every " + std::to_string(k) + suffix + " texel in u and v";
}

// A legend names each map up to this many; beyond (a virtual map's pages) the caption says what the
// colours are: the palette's, map by map, repeating.
constexpr size_t kMostNamedMaps = 16;

std::string caption(const Inspection& in, size_t surface, size_t drawn, int stride, std::optional<double> density) {
    const size_t maps = in.setup.maps.size();
    const std::string colours = maps > kMostNamedMaps
                                    ? ", a colour each (" + std::to_string(kMapPalette.size()) +
                                          " colours in turn, so that neighbouring maps differ; too many to name)"
                                    : ", a colour each";
    std::string text = "Texels — " + in.name() + ", " + std::to_string(in.resolution) + "² texture" +
                       (maps > 1 ? " of " + std::to_string(maps) + " maps" + colours + ", each where it serves" : "") +
                       ": " + std::to_string(surface) + " texels land on a surface (receivers too); " +
                       ordinal(stride) + " drawn (" + std::to_string(drawn) + "), each as its footprint there\n";
    if (density) {
        char mean[112];
        std::snprintf(mean, sizeof mean,
                      "%.2f texels per pixel where they are in the picture (one covers %.2f pixels); ", *density,
                      1.0 / *density);
        text += mean;
    }
    return text + "the scene dim, from its camera";
}

ViewReport build_texels_view(vtkRenderer* renderer, const Inspection& in, const ViewOptions&) {
    renderer->SetBackground(kSpaceBackground.r, kSpaceBackground.g, kSpaceBackground.b);
    // Through the scene's camera, drawn relative to the eye (float32 near it is as fine as anywhere).
    const glm::dvec3 origin = in.scene.camera.position;
    glm::dmat4 local_from_world(1.0);
    local_from_world[3] = glm::dvec4(-origin, 1.0);
    draw_dim_scene(renderer, in, local_from_world);
    Camera camera = in.scene.camera;
    camera.position -= origin;
    camera.target -= origin;
    place_scene_camera(renderer, camera);
    if (!in.has_map()) {
        add_caption(renderer,
                    in.title() + ": no shadow map, so no texels (a geometric technique; see the Stencil count view)");
        return {};
    }
    ViewReport report;
    if (const auto bent = std::find_if(in.setup.maps.begin(), in.setup.maps.end(),
                                       [](const ShadowMap& m) { return !projection_kind(m).projective(); });
        bent != in.setup.maps.end())
        report.notes.push_back(std::string(projection_kind(*bent).name) +
                               " maps' texels drawn flat between their back-projected corners (their edges bend)");

    const DepthMap& surfaces = in.surface_depth();
    const int stride = texel_stride(in.setup, surfaces, kMostQuads);
    const std::vector<WorldTexel> texels = world_texels(in.setup, surfaces, stride);
    auto quads = actor_for(texel_quads(texels, stride, origin), glm::dvec3(1.0));
    quads->GetProperty()->LightingOff();  // the map's colours exactly, whichever way a texel faces
    quads->GetProperty()->BackfaceCullingOff();
    renderer->AddActor(quads);
    if (in.setup.maps.size() > 1 && in.setup.maps.size() <= kMostNamedMaps) {
        std::vector<LegendEntry> legend;
        for (size_t i = 0; i < in.setup.maps.size(); ++i)
            legend.push_back({map_colour(static_cast<int>(i)), map_name(in.setup, i)});
        add_legend(renderer, legend);
    }
    add_caption(renderer, caption(in, surface_texels(in.setup, surfaces, 1), texels.size(), stride,
                                  texels_per_pixel(texels, in.scene.camera, renderer->GetSize())));
    return report;
}

}  // namespace

View texels_view() {
    return {.name = "texels",
            .title = "Texels",
            .prepare =
                [](const Inspection& in, const ViewOptions&) {
                    if (in.has_map()) in.surface_depth();
                },
            .build = build_texels_view,
            .choosers = {},
            .interaction = {.through_scene_camera = true, .drag = ViewDrag::orbits}};
}

}  // namespace shadowlab
