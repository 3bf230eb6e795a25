#include "methods/clipmap.hpp"

#include <cmath>

#include "math/invariant.hpp"

namespace shadowlab {

double Clipmap::texel(int level) const { return std::ldexp(finest_texel, level); }
double Clipmap::page_width(int level) const { return texel(level) * table.page_size; }

Clipmap clipmap_around(const ShadowInputs& in, const ClipmapSpec& spec) {
    assert_invariant(spec.page_size > 0 && spec.virtual_resolution % spec.page_size == 0);
    Clipmap c;
    c.light_from_world =
        light_basis(in.light.direction, stable_up_hint(in.light.direction), in.scene_bounds.center()).light_from_world;
    c.ls_camera = glm::dvec2(c.light_from_world * glm::dvec4(in.camera.position, 1.0));
    const double scene_radius = 0.5 * in.scene_bounds.diagonal();
    c.finest_texel = 2.0 * spec.first_level_radius * scene_radius / spec.virtual_resolution;
    c.table.pages_per_side = spec.virtual_resolution / spec.page_size;
    c.table.page_size = spec.page_size;
    const Aabb ls_scene = transformed(in.scene_bounds, c.light_from_world);
    for (int level = 0; level < spec.levels; ++level) {
        // The window about the camera, its corner on the level's page grid (a page is page_width wide).
        const double page = c.page_width(level), radius = 0.5 * page * c.table.pages_per_side;
        const glm::ivec2 first_page(glm::floor((c.ls_camera - radius) / page));
        const glm::dvec2 corner = glm::dvec2(first_page) * page;
        const Aabb ls_level{glm::dvec3(corner, ls_scene.min.z), glm::dvec3(corner + 2.0 * radius, ls_scene.max.z)};
        c.table.levels.push_back(
            {.world_to_uvz = orthographic_map(c.light_from_world, ls_level).world_to_uvz, .first_page = first_page});
    }
    c.table.resident.assign(std::size_t(spec.levels) * c.table.pages_per_side * c.table.pages_per_side, -1);
    return c;
}

double footprint_level(const Clipmap& c, double footprint) { return std::log2(footprint / c.finest_texel); }

int level_asked(double footprint_level, double bias) {
    const double level = std::floor(footprint_level + bias);
    return level > 0.0 ? static_cast<int>(std::min(level, 1e6)) : 0;  // NaN: the finest
}

}  // namespace shadowlab
