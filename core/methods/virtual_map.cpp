#include "methods/virtual_map.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

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
                    .dropped = allocation.dropped,
                    .bias_added = allocation.bias_added};
    table.marked = allocation.marks.marked;  // at the bias set: the pages the view needs
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

// The light-space depth range (page d, from 0 at the light) of the seen points each page of the
// table holds, in any level: where its receivers lie along its column. {1, 0} where it holds none.
std::vector<glm::dvec2> seen_depths(const PageTable& table, const SeenReceivers& seen) {
    std::vector<glm::dvec2> depths(table.resident.size(), glm::dvec2(1.0, 0.0));
    for (const glm::dvec3& p : seen.points)
        for (int level = 0; level < static_cast<int>(table.levels.size()); ++level)
            if (const std::optional<PageAddress> a = page_holding(table, level, p)) {
                const double d = (table.levels[level].world_to_uvz * glm::dvec4(p, 1.0)).z;
                glm::dvec2& range = depths[table.index(*a)];
                range = {std::min(range.x, d), std::max(range.y, d)};
            }
    return depths;
}

// Each page's box: its column cut to the depths of the seen points it holds (a sliver of the
// receivers' depth at least, so that a flat receiver's page still reads as a box), as edges, one
// set per level: hundreds of pages drawn as a few shapes, outlines that stay legible where they crowd.
std::vector<std::pair<int, SegmentSet>> page_boxes(const PageTable& table, const std::vector<PageAddress>& pages,
                                                   const std::vector<glm::dvec2>& depths) {
    constexpr double kLeastDepth = 0.01;
    std::vector<std::pair<int, SegmentSet>> out;
    for (const PageAddress& a : pages) {
        if (out.empty() || out.back().first != a.level) out.push_back({a.level, {}});
        glm::dvec2 range = depths[table.index(a)];
        if (range.x > range.y) range = {0.0, 1.0};  // no seen point: the whole column
        const double middle = 0.5 * (range.x + range.y), half = std::max(0.5 * (range.y - range.x), kLeastDepth / 2);
        range = {std::max(0.0, middle - half), std::min(1.0, middle + half)};
        const glm::dmat4 world_from_page = glm::inverse(page_world_to_uvz(table, a));
        auto corner = [&](int u, int v, int d) {
            const glm::dvec4 w = world_from_page * glm::dvec4(u, v, d ? range.y : range.x, 1.0);
            return glm::dvec3(w) / w.w;
        };
        auto& segments = out.back().second.segments;
        for (int d = 0; d < 2; ++d) {  // the two squares, then the four edges between them
            segments.push_back({corner(0, 0, d), corner(1, 0, d)});
            segments.push_back({corner(1, 0, d), corner(1, 1, d)});
            segments.push_back({corner(1, 1, d), corner(0, 1, d)});
            segments.push_back({corner(0, 1, d), corner(0, 0, d)});
        }
        for (const auto& [u, v] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}})
            segments.push_back({corner(u, v, 0), corner(u, v, 1)});
    }
    return out;
}

void record_levels(const Clipmap& c, const PageMarks& marks, const ShadowInputs& in, Trace* trace) {
    record(trace, [&](Trace& t) {
        const std::vector<int> levels = marked_levels(marks, c);
        Step& step = t.add("virtual-levels", "Clipmap levels",
                           "level l: half-width r0 2^l about the camera, snapped to whole pages of its grid; "
                           "texel 2 r0 2^l / virtual resolution",
                           Space::world)
                         .value("levels", double(c.levels()))
                         .value("finest texel", c.finest_texel)
                         .value("page width, level 0", c.page_width(0));
        // Each level as its square at the seen points' mean depth (the same d in every level): the
        // clipmap's nested windows about the camera, rather than columns through the whole scene.
        double depth = 0.5;
        if (in.seen_receivers && !in.seen_receivers->points.empty() && !levels.empty()) {
            double sum = 0.0;
            for (const glm::dvec3& p : in.seen_receivers->points)
                sum += (c.table.levels[levels.front()].world_to_uvz * glm::dvec4(p, 1.0)).z;
            depth = sum / double(in.seen_receivers->points.size());
        }
        for (int level : levels) {
            const glm::dmat4 world_from_level = glm::inverse(c.table.levels[level].world_to_uvz);
            std::vector<glm::dvec4> square;
            for (const auto& [u, v] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}})
                square.push_back(world_from_level * glm::dvec4(u, v, depth, 1.0));
            step.shape("level " + std::to_string(level), PolygonSet{}.add(square), Role::map);
        }
        draw_light(step, in.light, in.scene_bounds.center(), 0.25 * in.scene_bounds.diagonal());
        t.set_frame(Space::light, c.light_from_world);
    });
}

void record_marking(const Clipmap& c, const PageMarks& marks, const SeenReceivers& seen,
                    const std::vector<glm::dvec2>& depths, Trace* trace) {
    record(trace, [&](Trace& t) {
        // At most kShown points: enough to see where the view looks, few enough to draw at once.
        constexpr std::size_t kShown = 4096;
        PointSet shown;
        const std::size_t stride = std::max<std::size_t>(1, seen.points.size() / kShown);
        for (std::size_t i = 0; i < seen.points.size(); i += stride) shown.points.push_back(seen.points[i]);
        Step& step = t.add("virtual-marking", "Marking pages",
                           "each seen receiver point marks its page in level floor(log2(footprint / texel0) + bias); "
                           "a page drawn as its column cut to the depths of its points",
                           Space::world)
                         .value("points", double(marks.points))
                         .value("outside", double(marks.outside))
                         .value("pages marked", double(marks.count()))
                         .shape("seen points", shown, Role::receivers);
        for (auto& [level, boxes] : page_boxes(c.table, marked_pages(c.table, marks.marked), depths))
            step.shape("marked, level " + std::to_string(level), std::move(boxes), Role::focus);
    });
}

void record_allocation(const PageTable& table, const PageAllocation& a, const std::vector<glm::dvec2>& depths,
                       Trace* trace) {
    record(trace, [&](Trace& t) {
        Step& step =
            t.add("virtual-allocation", "Allocating slots",
                  "marked pages take slots up to the budget; beyond it the resolution bias rises until they fit",
                  Space::world)
                .value("marked", double(a.marked()))
                .value("bias added", a.bias_added)
                .value("resident", double(a.resident.size()))
                .value("budget", double(a.budget))
                .value("over budget", double(a.over_budget))
                .value("dropped", double(a.dropped));
        for (auto& [level, boxes] : page_boxes(table, table.pages, depths))
            step.shape("resident, level " + std::to_string(level), std::move(boxes), Role::map);
        std::vector<PageAddress> without;  // marked at the bias set, given no slot
        for (const PageAddress& p : marked_pages(table, table.marked))
            if (table.map_of(p) < 0) without.push_back(p);
        for (auto& [level, boxes] : page_boxes(table, without, depths))
            step.shape("over budget, level " + std::to_string(level), std::move(boxes), Role::receivers);
    });
}

// Does the box's shadow column meet the map's (u, v) square? Its corners' (u, v) span against [0,1]².
bool meets_page(const ShadowMap& map, const Aabb& box) {
    glm::dvec2 lo(1e300), hi(-1e300);
    for (const glm::dvec3& corner : box.corners()) {
        const glm::dvec4 uvz = map.world_to_uvz * glm::dvec4(corner, 1.0);  // orthographic: w = 1
        lo = glm::min(lo, glm::dvec2(uvz)), hi = glm::max(hi, glm::dvec2(uvz));
    }
    return lo.x <= 1.0 && hi.x >= 0.0 && lo.y <= 1.0 && hi.y >= 0.0;
}

// Step 4, rasterization: each resident page's casters drawn into its slot: shown as the casters'
// boxes that some resident page's column meets (those drawn at least once; UE5 culls the rest),
// and, as the output, the seen points a resident page holds (what reads the table) and those none
// holds (read lit).
void record_rasterization(const ShadowSetup& setup, const ShadowInputs& in, int page_size, Trace* trace) {
    record(trace, [&](Trace& t) {
        const double texels = double(setup.maps.size()) * page_size * page_size;
        Step& step = t.add("virtual-rasterization", "Rasterizing pages",
                           "each resident page: the casters its column meets drawn into its slot of the pool, "
                           "page_size² texels",
                           Space::world)
                         .value("pages drawn", double(setup.maps.size()))
                         .value("texels drawn", texels);
        int drawn = 0;
        for (const Aabb& box : in.casters)
            if (std::any_of(setup.maps.begin(), setup.maps.end(),
                            [&](const ShadowMap& map) { return meets_page(map, box); })) {
                step.shape("caster drawn", box, Role::casters);
                ++drawn;
            }
        step.value("casters drawn", double(drawn));
        PointSet held, unheld;
        if (in.seen_receivers) {
            constexpr std::size_t kShown = 4096;  // as the marking step shows them
            const std::vector<glm::dvec3>& points = in.seen_receivers->points;
            const std::size_t stride = std::max<std::size_t>(1, points.size() / kShown);
            for (std::size_t i = 0; i < points.size(); i += stride)
                (resident_map(setup.selection.pages, points[i]) >= 0 ? held : unheld).points.push_back(points[i]);
        }
        Step& output =
            t.add("output", "Page table", "a point reads the finest resident page that holds it", Space::world)
                .value("pages", double(setup.maps.size()))
                .shape("seen points a page holds", held, Role::step);
        if (!unheld.points.empty()) output.shape("seen points no page holds (lit)", unheld, Role::light);
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
    const std::vector<glm::dvec2> depths = trace ? seen_depths(c.table, *in.seen_receivers) : std::vector<glm::dvec2>{};
    record_levels(c, marks, in, trace);
    record_marking(c, marks, *in.seen_receivers, depths, trace);
    add_pages(c, allocation, pool, in.texture_resolution, setup);
    add_notes(marks, allocation, setup);
    record_allocation(setup.selection.pages, allocation, depths, trace);
    record_rasterization(setup, in, c.table.page_size, trace);
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
