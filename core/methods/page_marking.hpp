#pragma once
// Which pages of a virtual shadow map a view needs, and which of them the budget keeps.
#include <cstdint>
#include <vector>

#include "methods/clipmap.hpp"

namespace shadowlab {

// A pixel's width across its view ray at p, in world units: the image's height at p's view depth
// over its pixels (half_extent_at: growing with depth for a pinhole, fixed for an orthographic camera).
double footprint_width(const Camera& camera, int image_height, const glm::dvec3& p);

// Every seen point's footprint in levels (footprint_level), computed once for every marking.
std::vector<double> footprint_levels(const Clipmap& clipmap, const Camera& camera, const SeenReceivers& seen);

struct PageMarks {
    std::vector<std::uint8_t> marked;  // as PageTable::resident: 1 where a seen point needs the page
    int points = 0;                    // the seen points that marked a page
    int outside = 0;                   // seen points no level holds (beyond the coarsest): they read lit

    int count() const;  // marked pages
};

// Step 2, marking (UE5's page marking from the depth buffer): every seen receiver point marks the
// page holding it in the level its footprint asks for (level_asked, at most the coarsest), or in
// the finest coarser level whose window holds it. `levels`: footprint_levels of the seen points.
PageMarks mark_pages(const Clipmap& clipmap, const SeenReceivers& seen, const std::vector<double>& levels,
                     double resolution_bias);

// The pages marked in `marked` (as PageTable::resident), in slot order: level, then rows.
std::vector<PageAddress> marked_pages(const PageTable& table, const std::vector<std::uint8_t>& marked);

struct PageAllocation {
    std::vector<PageAddress> resident;  // in slot order: level, then rows of pages
    PageMarks marks;                    // as the view asked, at the resolution bias set
    int budget = 0;                     // physical slots: the setting, at most what the pool texture holds
    double bias_added = 0.0;            // levels added to the resolution bias to fit the budget (steps of 1/8)
    int over_budget = 0;                // marked pages that got no slot: their points read a coarser level
    int dropped = 0;                    // coarsest-level pages left without a slot: their points read lit

    int marked() const { return marks.count(); }
};

// Step 3, allocation: when the marked pages fit the budget, each gets a slot. Beyond it, the excess
// falls to coarser levels evenly, as UE5's dynamic resolution does: the resolution bias is raised
// (in steps of 1/8 of a level, the least that fits) and the pages marked again, every point losing
// the same share of its resolution rather than a few losing all of it. Should even the coarsest
// marking not fit, its pages farthest from the camera go without.
PageAllocation allocate_pages(const Clipmap& clipmap, const Camera& camera, const SeenReceivers& seen,
                              double resolution_bias, int budget);

}  // namespace shadowlab
