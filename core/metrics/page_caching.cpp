#include "metrics/page_caching.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include "maps/map_lookup.hpp"

namespace shadowlab {
namespace {

using GridKey = std::tuple<int, int, int>;  // level, grid x, grid y

// The setup's resident pages by their world-anchored keys, sorted; none without a page table.
std::vector<GridKey> grid_keys(const ShadowSetup& setup) {
    std::vector<GridKey> keys;
    if (setup.selection.rule != MapSelection::Rule::pages) return keys;
    const PageTable& table = setup.selection.pages;
    for (const PageAddress& a : table.pages) {
        const glm::ivec2 g = grid_page(table, a);
        keys.emplace_back(a.level, g.x, g.y);
    }
    std::sort(keys.begin(), keys.end());
    return keys;
}

}  // namespace

std::vector<bool> kept_maps(const ShadowSetup* before, const ShadowSetup& now) {
    std::vector<bool> kept(now.maps.size(), false);
    if (!before || now.selection.rule != MapSelection::Rule::pages) return kept;
    const std::vector<GridKey> then = grid_keys(*before);
    const PageTable& table = now.selection.pages;
    for (std::size_t map = 0; map < table.pages.size(); ++map) {
        const glm::ivec2 g = grid_page(table, table.pages[map]);
        kept[map] = std::binary_search(then.begin(), then.end(), GridKey{table.pages[map].level, g.x, g.y});
    }
    return kept;
}

PageTurnover page_turnover(const ShadowSetup* before, const ShadowSetup& now) {
    const std::vector<GridKey> then = before ? grid_keys(*before) : std::vector<GridKey>{}, here = grid_keys(now);
    std::vector<GridKey> both;
    std::set_intersection(then.begin(), then.end(), here.begin(), here.end(), std::back_inserter(both));
    return {.allocated = here.size() - both.size(), .kept = both.size(), .freed = then.size() - both.size()};
}

double texels_in_tiles(const ShadowSetup& setup, int resolution) {
    double texels = 0.0;
    for (const ShadowMap& map : setup.maps) texels += std::pow(tile_resolution(map, resolution), 2);
    return texels;
}

double texels_drawn(const ShadowSetup& setup, const PageTurnover& turnover, int resolution) {
    if (setup.selection.rule != MapSelection::Rule::pages || setup.maps.empty())
        return texels_in_tiles(setup, resolution);
    return double(turnover.allocated) * std::pow(tile_resolution(setup.maps.front(), resolution), 2);
}

}  // namespace shadowlab
