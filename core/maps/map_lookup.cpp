#include "maps/map_lookup.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/preimage.hpp"
#include "maps/projection_kind.hpp"

namespace shadowlab {
namespace {

bool in_unit_range(double t) { return t >= 0.0 && t <= 1.0; }  // false for NaN

// The map whose face axis has the largest dot with r, the first on ties. The faces of a polyhedron
// about the centre (a cube's, a tetrahedron's, their axes the directions to the faces' centres)
// share its sphere of directions so: r meets the face plane dot(x, a) = h at h / dot(r, a), the
// nearest plane first. For a cube's axes in the order +x, -x, +y, -y, +z, -z it is the major axis.
int nearest_face(const ShadowSetup& setup, const glm::dvec3& r) {
    int best = 0;
    for (int i = 1; i < int(setup.maps.size()); ++i)
        if (glm::dot(setup.maps[i].face_axis, r) > glm::dot(setup.maps[best].face_axis, r)) best = i;
    return best;
}

int first_map(const ShadowSetup& setup, auto&& holds) {
    for (int i = 0; i < int(setup.maps.size()); ++i)
        if (holds(setup.maps[i])) return i;
    return -1;
}

double view_depth(const MapSelection& s, const glm::dvec3& world) { return glm::dot(world - s.eye, s.view_axis); }

// The split depths the rule reads: one more than the maps at most.
int split_count(const ShadowSetup& setup) {
    return int(std::min(setup.selection.split_depths.size(), setup.maps.size() + 1));
}

int by_view_depth(const ShadowSetup& setup, const glm::dvec3& world) {
    const MapSelection& s = setup.selection;
    const double depth = view_depth(s, world);
    const int splits = split_count(setup);
    for (int i = 0; i + 1 < splits; ++i)
        if (depth >= s.split_depths[i] &&
            (depth < s.split_depths[i + 1] || (i + 2 == splits && depth == s.split_depths[i + 1])))
            return i;
    return -1;
}

bool on_map(const glm::dvec4& h) { return h.w > 0.0 && in_unit_range(h.x / h.w) && in_unit_range(h.y / h.w); }

}  // namespace

const char* to_string(MapSelection::Rule rule) {
    switch (rule) {
        case MapSelection::Rule::only: return "one map";
        case MapSelection::Rule::view_depth: return "by view depth";
        case MapSelection::Rule::tile_bounds: return "by tile bounds";
        case MapSelection::Rule::face_axis: return "by face axis";
        case MapSelection::Rule::hemisphere: return "by hemisphere";
        case MapSelection::Rule::pages: return "by page";
    }
    return "?";
}

glm::dvec4 map_homogeneous(const ShadowMap& map, const glm::dvec3& world) {
    return projection_kind(map).homogeneous(map, world);
}

ShadowMap with_reversed_depth(const ShadowMap& map) { return projection_kind(map).reversed_depth(map); }

glm::dvec3 world_to_uvz(const ShadowMap& map, const glm::dvec3& world) {
    const glm::dvec4 h = map_homogeneous(map, world);
    return glm::dvec3(h) / h.w;
}

double hemisphere_side(const ShadowMap& map, const glm::dvec3& world) {
    const ProjectionKind& kind = projection_kind(map);
    return kind.clip_distance ? kind.clip_distance(map, world) : 1.0;
}

int select_map(const ShadowSetup& setup, const glm::dvec3& world) {
    if (setup.maps.empty()) return -1;
    switch (setup.selection.rule) {
        case MapSelection::Rule::only: return 0;
        case MapSelection::Rule::view_depth: return by_view_depth(setup, world);
        case MapSelection::Rule::tile_bounds:
            return first_map(setup, [&](const ShadowMap& m) { return on_map(map_homogeneous(m, world)); });
        case MapSelection::Rule::face_axis: return nearest_face(setup, world - setup.selection.centre);
        case MapSelection::Rule::hemisphere:
            return first_map(setup, [&](const ShadowMap& m) { return hemisphere_side(m, world) >= 0.0; });
        case MapSelection::Rule::pages: return resident_map(setup.selection.pages, world);
    }
    return -1;
}

MapBlend blend_of(const ShadowSetup& setup, const glm::dvec3& world) {
    const int map = select_map(setup, world);
    const MapSelection& s = setup.selection;
    const bool has_next = map >= 0 && map + 2 < split_count(setup);
    if (s.rule != MapSelection::Rule::view_depth || !(s.blend_band > 0.0) || !has_next) return {.map = map};
    const double far = s.split_depths[map + 1];
    const double band = s.blend_band * (far - s.split_depths[map]);
    const double weight = std::clamp((view_depth(s, world) - (far - band)) / band, 0.0, 1.0);
    if (!(weight > 0.0)) return {.map = map};
    return {.map = map, .next = map + 1, .weight = weight};
}

Frustum map_volume(const ShadowMap& map) {
    return preimage_of_box(map.world_to_uvz, Aabb{glm::dvec3(0.0), glm::dvec3(1.0)});
}

double tile_resolution(const ShadowMap& map, int texture_resolution) {
    // Tiles are square: their width in texels is their height.
    return (map.viewport.z - map.viewport.x) * texture_resolution;
}

glm::dvec2 texture_uv(const ShadowMap& map, const glm::dvec2& uv) {
    const glm::dvec2 lo(map.viewport.x, map.viewport.y), hi(map.viewport.z, map.viewport.w);
    return lo + uv * (hi - lo);
}

glm::ivec2 texel_of(const ShadowMap& map, const glm::dvec2& uv, int texture_resolution) {
    const double n = texture_resolution;
    const glm::ivec2 first(int(std::lround(map.viewport.x * n)), int(std::lround(map.viewport.y * n)));
    const glm::ivec2 last(int(std::lround(map.viewport.z * n)) - 1, int(std::lround(map.viewport.w * n)) - 1);
    const glm::dvec2 t = texture_uv(map, uv) * n;
    return glm::clamp(glm::ivec2(int(std::floor(t.x)), int(std::floor(t.y))), first, last);
}

std::optional<MapPoint> map_point(const ShadowSetup& setup, const glm::dvec3& world) {
    const int i = select_map(setup, world);
    if (i < 0) return std::nullopt;
    const glm::dvec4 h = map_homogeneous(setup.maps[i], world);
    if (!(h.w > 0.0)) return std::nullopt;
    return MapPoint{i, h};
}

std::optional<MapLookup> look_up(const ShadowSetup& setup, const glm::dvec3& world, double bias) {
    return look_up_in(setup, select_map(setup, world), world, bias);
}

std::optional<MapLookup> look_up_in(const ShadowSetup& setup, int map, const glm::dvec3& world, double bias) {
    if (map < 0) return std::nullopt;
    const glm::dvec4 h = map_homogeneous(setup.maps[map], world);
    if (!on_map(h)) return std::nullopt;
    return MapLookup{map, glm::dvec2(h) / h.w, (h.z - setup.maps[map].z_bias_scale * bias) / h.w};
}

glm::dvec2 uv_derivative(const ShadowMap& map, const glm::dvec3& p, const glm::dvec3& direction) {
    return projection_kind(map).uv_derivative(map, p, direction);
}

ShadowSetup relative_to(ShadowSetup setup, const glm::dvec3& origin) {
    glm::dmat4 world_from_local(1.0);
    world_from_local[3] = glm::dvec4(origin, 1.0);
    for (ShadowMap& map : setup.maps) {
        map.world_to_uvz = map.world_to_uvz * world_from_local;
        map.paraboloid.centre -= origin;
    }
    for (PageLevel& level : setup.selection.pages.levels) level.world_to_uvz = level.world_to_uvz * world_from_local;
    setup.selection.eye -= origin;
    setup.selection.centre -= origin;
    return setup;
}

double depth_slope(const ShadowMap& map, const glm::dvec3& l, const glm::dvec3& p) {
    return projection_kind(map).depth_slope(map, l, p);
}

double distance_back_to_depth(const ShadowMap& map, const glm::dvec3& l, const glm::dvec3& p, double depth) {
    return projection_kind(map).distance_back_to_depth(map, l, p, depth);
}

double world_per_depth_unit(const ShadowMap& map, const glm::dvec3& l, const glm::dvec3& p) {
    const double slope = depth_slope(map, l, p);
    return slope > 0.0 ? 1.0 / slope : INFINITY;
}

}  // namespace shadowlab
