#pragma once
// The integral over a plane of the largest of several densities, each known over a parallelogram
// (a pixel's footprint and the density it asks for there), where the parallelograms of one surface
// tile the plane and those of surfaces one behind the other overlap: ∫ max_i ρ_i 1[q ∈ P_i] dq.
//
// A multi-level grid (a sparse quadtree of square cells, level l of side 2^-l, on each chart of the
// plane): each parallelogram is drawn into the level whose cells are the largest no wider than the
// square root of its area (so a footprint covers one to four cells and the level resolves it),
// marking every cell whose centre it holds with its density, the largest kept per cell.
// Parallelograms that tile the plane at one level mark each centre once, so their union is drawn
// to within half a cell along its outline. The integral then takes, at every point, the largest
// value of the cells holding it at any level: a coarse cell's value reaches into its finer
// descendants, so where a sparse surface lies behind a dense one (or beside it) the dense one
// counts wherever both are. Exact for the cells as marked; the marking misses up to half a coarse
// cell of the coarser footprints along the lines where the level changes (a density that varies
// across the plane comes out a few per cent low: a lower bound stays one).
//
// Densities come in pairs integrated at once, each on its own (a bound over all the footprints and
// over a subset of them: 0 where a footprint is not in the subset).
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <glm/glm.hpp>

namespace shadowlab {

class MaxDensityGrid {
public:
    // The parallelogram centre + a·edge_a + b·edge_b, |a|, |b| <= 1/2, on `chart`, asking `density`
    // (per unit area) there. A degenerate one (no area) marks nothing.
    void add(int chart, const glm::dvec2& centre, const glm::dvec2& edge_a, const glm::dvec2& edge_b,
             const glm::dvec2& densities);

    // ∫ max density over every chart, each of the pair.
    glm::dvec2 integral() const;

    size_t cells() const { return marked_.size(); }

private:
    struct Cell {
        int chart = 0, level = 0;
        std::int64_t x = 0, y = 0;  // the cell [x, x + 1) × [y, y + 1) in units of 2^-level
        bool operator==(const Cell&) const = default;
        Cell parent() const {  // >> floors negatives (C++20)
            return {.chart = chart, .level = level - 1, .x = x >> 1, .y = y >> 1};
        }
    };
    struct CellHash {
        size_t operator()(const Cell& c) const;
    };

    void mark(const Cell& cell, const glm::vec2& densities);
    glm::dvec2 integral_under(const Cell& cell, const glm::dvec2& inherited,
                              const std::unordered_set<Cell, CellHash>& inner) const;

    std::unordered_map<Cell, glm::vec2, CellHash> marked_;  // the largest densities drawn into each cell
};

}  // namespace shadowlab
