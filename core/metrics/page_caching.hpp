#pragma once
// What a virtual shadow map's page cache saves along a camera path (UE5 keeps pages from frame to
// frame and redraws only what is new or moved): a page is the same page in the next frame when it
// holds the same level and the same square of that level's world-anchored grid (maps/page_table.hpp).
// Over a static scene a kept page's texels are those it would be drawn with again, so a frame draws
// only the pages it newly allocates. A setup without pages keeps nothing: it draws every tile.
#include <cstddef>
#include <vector>

#include "maps/shadow_map.hpp"

namespace shadowlab {

struct PageTurnover {
    std::size_t allocated = 0;  // resident now, not the frame before: drawn
    std::size_t kept = 0;       // resident in both: their texels kept
    std::size_t freed = 0;      // resident the frame before, not now
};

// Per map of `now`: whether `before` held the same page (false for every map of a setup without a
// page table, or with no frame before).
std::vector<bool> kept_maps(const ShadowSetup* before, const ShadowSetup& now);

// From one frame's setup to the next's (`before` null for the first frame: every page allocated).
PageTurnover page_turnover(const ShadowSetup* before, const ShadowSetup& now);

// The texels a frame draws: every tile's without a cache (fresh), only the allocated pages' with one.
double texels_in_tiles(const ShadowSetup& setup, int resolution);
double texels_drawn(const ShadowSetup& setup, const PageTurnover& turnover, int resolution);

}  // namespace shadowlab
