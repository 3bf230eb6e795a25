#pragma once
// A virtual shadow map's page table (Unreal Engine 5's virtual shadow maps; Fernando et al. 2001's
// adaptive shadow maps before them): clipmap levels of one orthographic light view, each a virtual
// map of pages_per_side² pages of page_size² texels, each level's texel twice the one before. Only
// the pages a view needs are resident; each resident page is one map of the setup, drawn into its
// slot of the physical pool (the setup's texture), and a point reads the finest resident page that
// holds it (MapSelection::Rule::pages, maps/map_lookup.hpp).
#include <cstdint>
#include <optional>
#include <vector>
#include <glm/glm.hpp>

namespace shadowlab {

// One clipmap level: its whole virtual map, and where it lies in the level's page grid, which is
// anchored in the world (page (0, 0) of every level starts at the same light-space point), so that a
// page keeps its texels while the camera moves and the level slides by whole pages.
struct PageLevel {
    glm::dmat4 world_to_uvz{1.0};  // orthographic: (u, v, d) in [0,1]³ over the level, w = 1
    glm::ivec2 first_page{0};      // the grid page at the level's (u, v) = (0, 0)
};

// A page of one level, by its place in the level: 0 <= x, y < pages_per_side.
struct PageAddress {
    int level = 0;
    glm::ivec2 page{0};

    bool operator==(const PageAddress&) const = default;
};

// What a view's allocation did: the pages it marked, the physical slots, the marked pages that fell
// to a coarser level for want of a slot, the coarsest ones left without one, and the levels added
// to the resolution bias to fit the budget.
struct PageCounts {
    int marked = 0, budget = 0, over_budget = 0, dropped = 0;
    double bias_added = 0.0;
};

// A page of the table as the view left it.
enum class PageState {
    empty,        // neither marked nor resident
    needed,       // marked by the view (at the resolution bias set) and resident
    raised,       // resident, not marked at the bias set: marked once the bias was raised to fit the budget
    over_budget,  // marked at the bias set but given no slot: its points read a coarser resident page, or lit
};

struct PageTable {
    std::vector<PageLevel> levels;  // finest first
    int pages_per_side = 0;         // virtual resolution / page_size
    int page_size = 0;              // texels per page side
    // levels × pages_per_side², level-major, rows of y: the setup's map that holds each page, -1 where
    // the page is not resident.
    std::vector<int> resident;
    std::vector<PageAddress> pages;  // map i of the setup holds pages[i]
    // As resident: 1 where the view marked the page at the resolution bias set (counts.marked of
    // them), before any bias was added; empty when nothing was marked (a table built by hand).
    std::vector<std::uint8_t> marked;
    PageCounts counts;

    int map_of(const PageAddress& a) const { return resident[index(a)]; }
    std::size_t index(const PageAddress& a) const {
        return (std::size_t(a.level) * pages_per_side + a.page.y) * pages_per_side + a.page.x;
    }
};

// The page's state: its mark (none when `marked` is empty) and whether a map holds it.
PageState page_state(const PageTable& table, const PageAddress& page);

// The page of `level` that holds the world point (its (u, v) in [0,1)², the far edge in the last
// page), nullopt outside the level.
std::optional<PageAddress> page_holding(const PageTable& table, int level, const glm::dvec3& world);

// The finest resident page that holds the point, and the setup's map holding it; -1 for none.
int resident_map(const PageTable& table, const glm::dvec3& world);

// A (u, v) of the page map `map` holds, read beyond its square's edge (a filter's tap): the page
// of the same level it falls in, resident, and the (u, v) there, its square `offset` whole pages
// from the first. nullopt inside the square, beyond the level, where that page is not resident,
// and for a map that is no page (a table without pages: every other setup).
struct PageAcross {
    int map = -1;
    glm::dvec2 uv{0.0};
    glm::ivec2 offset{0};
};
std::optional<PageAcross> page_across(const PageTable& table, int map, const glm::dvec2& uv);

// The page's own (u, v, d): the level's map with its (u, v) square cut to the page's, so that the
// page is a linear map of its own and every reader of maps reads it as one.
glm::dmat4 page_world_to_uvz(const PageTable& table, const PageAddress& page);

// The page's place in the world-anchored grid of its level (first_page + page): what stays the
// same page from one frame to the next.
glm::ivec2 grid_page(const PageTable& table, const PageAddress& page);

}  // namespace shadowlab
