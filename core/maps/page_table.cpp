#include "maps/page_table.hpp"

#include <cmath>

namespace shadowlab {

std::optional<PageAddress> page_holding(const PageTable& table, int level, const glm::dvec3& world) {
    const glm::dvec4 uvz = table.levels[level].world_to_uvz * glm::dvec4(world, 1.0);  // w = 1: orthographic
    if (!(uvz.x >= 0.0 && uvz.x <= 1.0 && uvz.y >= 0.0 && uvz.y <= 1.0)) return std::nullopt;
    const int last = table.pages_per_side - 1;
    auto page = [&](double t) { return std::min(static_cast<int>(t * table.pages_per_side), last); };
    return PageAddress{.level = level, .page = {page(uvz.x), page(uvz.y)}};
}

int resident_map(const PageTable& table, const glm::dvec3& world) {
    for (int level = 0; level < static_cast<int>(table.levels.size()); ++level) {
        const std::optional<PageAddress> page = page_holding(table, level, world);
        if (!page) continue;  // beyond this level: a coarser one may hold it
        if (const int map = table.map_of(*page); map >= 0) return map;
    }
    return -1;
}

std::optional<PageAcross> page_across(const PageTable& table, int map, const glm::dvec2& uv) {
    if (map < 0 || std::size_t(map) >= table.pages.size()) return std::nullopt;
    if (uv.x >= 0.0 && uv.x < 1.0 && uv.y >= 0.0 && uv.y < 1.0) return std::nullopt;  // its own square
    const glm::ivec2 offset(int(std::floor(uv.x)), int(std::floor(uv.y)));
    const PageAddress& own = table.pages[map];
    const PageAddress there{.level = own.level, .page = own.page + offset};
    const int n = table.pages_per_side;
    if (there.page.x < 0 || there.page.y < 0 || there.page.x >= n || there.page.y >= n) return std::nullopt;
    const int neighbour = table.map_of(there);
    if (neighbour < 0) return std::nullopt;
    return PageAcross{.map = neighbour, .uv = uv - glm::dvec2(offset), .offset = offset};
}

glm::dmat4 page_world_to_uvz(const PageTable& table, const PageAddress& a) {
    // u' = u n - x, v' = v n - y (n pages per side); d unchanged.
    const double n = table.pages_per_side;
    glm::dmat4 page_from_level(1.0);
    page_from_level[0][0] = n;
    page_from_level[1][1] = n;
    page_from_level[3] = glm::dvec4(-a.page.x, -a.page.y, 0.0, 1.0);
    return page_from_level * table.levels[a.level].world_to_uvz;
}

PageState page_state(const PageTable& table, const PageAddress& a) {
    const std::size_t i = table.index(a);
    const bool marked = i < table.marked.size() && table.marked[i] != 0, resident = table.resident[i] >= 0;
    if (marked) return resident ? PageState::needed : PageState::over_budget;
    return resident ? PageState::raised : PageState::empty;
}

glm::ivec2 grid_page(const PageTable& table, const PageAddress& a) { return table.levels[a.level].first_page + a.page; }

}  // namespace shadowlab
