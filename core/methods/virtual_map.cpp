#include "methods/virtual_map.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "io/value_text.hpp"
#include "maps/map_lookup.hpp"
#include "methods/map_fit.hpp"
#include "methods/page_marking.hpp"
#include "methods/step_figures.hpp"
#include "methods/uniform.hpp"

namespace shadowlab {
namespace {

ClipmapSpec clipmap_spec(const Settings& s) {
    return {.levels = static_cast<int>(s.number("levels")),
            .first_level_radius = s.number("first_level_radius"),
            .virtual_resolution = std::stoi(s.choice("virtual_resolution")),
            .page_size = std::stoi(s.choice("page_size"))};
}

// The physical pool: the setup's texture in slots of page_size texels, as many as the budget asks
// and the texture holds.
struct Pool {
    int slots_per_side = 0;
    int budget = 0;
};
Pool pool_of(const Settings& s, int texture_resolution, int page_size) {
    const int side = texture_resolution / page_size;
    return {.slots_per_side = side, .budget = std::min(static_cast<int>(s.number("page_budget")), side * side)};
}

// Slot k of the pool, in rows: its tile of the texture, on texel boundaries.
glm::dvec4 slot_viewport(int k, const Pool& pool, int page_size, int texture_resolution) {
    const glm::dvec2 first = glm::dvec2(k % pool.slots_per_side, k / pool.slots_per_side) * double(page_size);
    const glm::dvec2 last = first + double(page_size);
    return glm::dvec4(first, last) / double(texture_resolution);
}

// Step 4's maps: each resident page its level's map cut to the page, in its slot.
void add_pages(const Clipmap& c, const PageAllocation& allocation, const Pool& pool, int texture_resolution,
               ShadowSetup& setup) {
    PageTable table = c.table;
    table.counts = {.marked = allocation.marked(),
                    .budget = allocation.budget,
                    .over_budget = allocation.over_budget,
                    .dropped = allocation.dropped};
    for (const PageAddress& a : allocation.resident) {
        const int map = static_cast<int>(setup.maps.size());
        table.resident[table.index(a)] = map;
        table.pages.push_back(a);
        setup.maps.push_back({.world_to_uvz = page_world_to_uvz(table, a),
                              .viewport = slot_viewport(map, pool, table.page_size, texture_resolution)});
    }
    setup.selection = {.rule = MapSelection::Rule::pages, .pages = std::move(table)};
}

void add_notes(const PageMarks& marks, const PageAllocation& a, ShadowSetup& setup) {
    if (a.over_budget > 0 || a.dropped > 0)
        add_fallback(setup, {NoteKind::over_page_budget,
                             std::to_string(a.marked()) + " pages marked for a budget of " + std::to_string(a.budget) +
                                 ": the resolution bias raised by " + significant(a.bias_added, 3) + " level(s), " +
                                 std::to_string(a.over_budget) + " pages fewer" +
                                 (a.dropped > 0 ? ", " + std::to_string(a.dropped) + " left without a slot" : "")});
    if (marks.outside > 0)
        add_fallback(setup, {NoteKind::outside_clipmap,
                             std::to_string(marks.outside) + " seen points beyond the coarsest level read lit"});
}

ShadowMap level_map(const Clipmap& c, int level) { return {.world_to_uvz = c.table.levels[level].world_to_uvz}; }

// The levels that hold a marked page, finest first.
std::vector<int> marked_levels(const PageMarks& marks, const Clipmap& c) {
    std::vector<int> levels;
    const std::size_t per_level = std::size_t(c.table.pages_per_side) * c.table.pages_per_side;
    for (int level = 0; level < c.levels(); ++level) {
        const auto first = marks.marked.begin() + std::ptrdiff_t(level * per_level);
        if (std::find(first, first + std::ptrdiff_t(per_level), 1) != first + std::ptrdiff_t(per_level))
            levels.push_back(level);
    }
    return levels;
}

// A page's world volume: the level's map volume cut to the page.
Frustum page_volume(const PageTable& table, const PageAddress& a) {
    return map_volume(ShadowMap{.world_to_uvz = page_world_to_uvz(table, a)});
}

void record_levels(const Clipmap& c, const std::vector<int>& levels, const ShadowInputs& in, Trace* trace) {
    record(trace, [&](Trace& t) {
        Step& step = t.add("virtual-levels", "Clipmap levels",
                           "level l: half-width r0 2^l about the camera, snapped to whole pages of its grid; "
                           "texel 2 r0 2^l / virtual resolution",
                           Space::world)
                         .value("levels", double(c.levels()))
                         .value("finest texel", c.finest_texel)
                         .value("page width, level 0", c.page_width(0));
        for (int level : levels)
            step.shape("level " + std::to_string(level), map_volume(level_map(c, level)), Role::map);
        draw_light(step, in.light, in.scene_bounds.center(), 0.25 * in.scene_bounds.diagonal());
        t.set_frame(Space::light, c.light_from_world);
    });
}

void record_marking(const Clipmap& c, const PageMarks& marks, const SeenReceivers& seen, Trace* trace) {
    record(trace, [&](Trace& t) {
        // At most kShown points: enough to see where the view looks, few enough to draw at once.
        constexpr std::size_t kShown = 4096;
        PointSet shown;
        const std::size_t stride = std::max<std::size_t>(1, seen.points.size() / kShown);
        for (std::size_t i = 0; i < seen.points.size(); i += stride) shown.points.push_back(seen.points[i]);
        Step& step = t.add("virtual-marking", "Marking pages",
                           "each seen receiver point marks its page in level floor(log2(footprint / texel0) + bias)",
                           Space::world)
                         .value("points", double(marks.points))
                         .value("outside", double(marks.outside))
                         .value("pages marked", double(marks.count()))
                         .shape("seen points", shown, Role::receivers);
        for (int level = 0; level < c.levels(); ++level)
            for (int y = 0; y < c.table.pages_per_side; ++y)
                for (int x = 0; x < c.table.pages_per_side; ++x)
                    if (const PageAddress a{level, {x, y}}; marks.marked[c.table.index(a)])
                        step.shape("marked " + std::to_string(level), page_volume(c.table, a), Role::focus);
    });
}

void record_allocation(const ShadowSetup& setup, const PageAllocation& a, Trace* trace) {
    record(trace, [&](Trace& t) {
        Step& step =
            t.add("virtual-allocation", "Allocating slots",
                  "marked pages take slots up to the budget; beyond it the finest, farthest fall a level", Space::world)
                .value("marked", double(a.marked()))
                .value("bias added", a.bias_added)
                .value("resident", double(a.resident.size()))
                .value("budget", double(a.budget))
                .value("over budget", double(a.over_budget))
                .value("dropped", double(a.dropped));
        for (std::size_t i = 0; i < setup.maps.size(); ++i)
            step.map_shape(int(i), "page", map_volume(setup.maps[i]), Role::map);
    });
}

// Step 4, rasterization: each resident page's casters drawn into its slot. Shown as the light-facing
// squares of the pages (near faces), where the casters are seen from.
void record_rasterization(const ShadowSetup& setup, int page_size, Trace* trace) {
    record(trace, [&](Trace& t) {
        PolygonSet squares;
        for (const ShadowMap& map : setup.maps) {
            const Frustum volume = map_volume(map);
            const auto& c = volume.corners;  // the near face first
            squares.add({glm::dvec4(c[0], 1.0), glm::dvec4(c[1], 1.0), glm::dvec4(c[2], 1.0), glm::dvec4(c[3], 1.0)});
        }
        const double texels = double(setup.maps.size()) * page_size * page_size;
        t.add("virtual-rasterization", "Rasterizing pages",
              "each resident page: its casters drawn into its slot of the pool, page_size² texels", Space::world)
            .value("pages drawn", double(setup.maps.size()))
            .value("texels drawn", texels)
            .shape("drawn pages", squares, Role::casters);
        t.add("output", "Page table", "a point reads the finest resident page that holds it", Space::world)
            .value("pages", double(setup.maps.size()));
        if (!setup.maps.empty()) t.set_frame(Space::unit, setup.maps.front().world_to_uvz);
    });
}

}  // namespace

ShadowSetup compute_virtual(const ShadowInputs& in, const Settings& s, Trace* trace) {
    ShadowSetup setup;
    if (!in.light.is_directional() || !in.seen_receivers) {
        add_fallback(setup, in.light.is_directional() ? Note{NoteKind::no_depth_image,
                                                             "virtual pages are marked from the camera's depth "
                                                             "image, not measured here: the uniform map"}
                                                      : Note{NoteKind::not_directional,
                                                             "virtual maps are clipmaps of a directional light: "
                                                             "the uniform map"});
        fit_uniform(in, setup, trace);
        return setup;
    }
    const Clipmap c = clipmap_around(in, clipmap_spec(s));
    const Pool pool = pool_of(s, in.texture_resolution, c.table.page_size);
    const PageAllocation allocation =
        allocate_pages(c, in.camera, *in.seen_receivers, s.number("resolution_bias"), pool.budget);
    const PageMarks& marks = allocation.marks;
    record_levels(c, marked_levels(marks, c), in, trace);
    record_marking(c, marks, *in.seen_receivers, trace);
    add_pages(c, allocation, pool, in.texture_resolution, setup);
    add_notes(marks, allocation, setup);
    record_allocation(setup, allocation, trace);
    record_rasterization(setup, c.table.page_size, trace);
    return setup;
}

std::vector<SettingSpec> virtual_settings() {
    return {{.name = "levels",
             .description = "clipmap levels, each twice the radius of the one before (UE5: 17, levels 6 to 22)",
             .default_value = "16",
             .min = 1,
             .max = 24},
            {.name = "first_level_radius",
             .description = "the finest level's half-width, a share of the scene's bounding radius",
             .default_value = "0.015625",
             .min = 1e-5,
             .max = 1.0},
            {.name = "virtual_resolution",
             .description = "texels per side of each level's virtual map (UE5: 16384)",
             .default_value = "16384",
             .choices = {"16384", "32768", "8192", "4096", "2048"}},
            {.name = "page_size",
             .description = "texels per page side (UE5: 128)",
             .default_value = "128",
             .choices = {"128", "64", "256", "32"}},
            {.name = "page_budget",
             .description = "physical pages at most, within what the map's texture holds (UE5: 4096)",
             .default_value = "4096",
             .min = 1,
             .max = 1 << 20},
            {.name = "resolution_bias",
             .description = "levels added to the one a pixel's footprint asks for: + coarser, - finer",
             .default_value = "0",
             .min = -4.0,
             .max = 4.0}};
}

bool virtual_reads_visible_depths(const Settings&) { return true; }

std::optional<SettingsChange> virtual_finer_texels(const Settings& s, double factor) {
    constexpr double kLeastBias = -4.0;  // the setting's range
    const double bias = s.number("resolution_bias");
    const double finer = std::max(kLeastBias, bias - std::max(1.0, std::ceil(std::log2(factor))));
    if (!(finer < bias)) return std::nullopt;
    SettingsChange out{.settings = s,
                       .change = "resolution_bias " + significant(bias, 3) + " → " + significant(finer, 3)};
    out.settings.set("resolution_bias", finer);
    return out;
}

}  // namespace shadowlab
