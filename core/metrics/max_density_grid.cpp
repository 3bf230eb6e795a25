#include "metrics/max_density_grid.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace shadowlab {
namespace {

// SplitMix64's finalizer: every input bit moves every output bit.
std::uint64_t mixed(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

// The cells along one axis whose centres ((k + 1/2) side) lie in [lo, hi].
struct CellRange {
    std::int64_t first, last;
};
CellRange centres_within(double lo, double hi, double side) {
    return {std::int64_t(std::ceil(lo / side - 0.5)), std::int64_t(std::floor(hi / side - 0.5))};
}

// The offsets t along x, within [lo, hi], for which |base + slope t| <= 1/2 in both coordinates:
// where a row of cell centres crosses the parallelogram (its (a, b) coordinates in [-1/2, 1/2]).
bool clip_to_parallelogram(const glm::dvec2& base, const glm::dvec2& slope, double& lo, double& hi) {
    for (int k = 0; k < 2; ++k) {
        if (slope[k] == 0.0) {
            if (std::abs(base[k]) > 0.5) return false;
            continue;
        }
        const double t1 = (-0.5 - base[k]) / slope[k], t2 = (0.5 - base[k]) / slope[k];
        lo = std::max(lo, std::min(t1, t2));
        hi = std::min(hi, std::max(t1, t2));
    }
    return lo <= hi;
}

}  // namespace

size_t MaxDensityGrid::CellHash::operator()(const Cell& c) const {
    const std::uint64_t level_chart = (std::uint64_t(std::uint32_t(c.level)) << 8) ^ std::uint64_t(c.chart);
    return size_t(mixed(mixed(mixed(level_chart) ^ std::uint64_t(c.x)) ^ std::uint64_t(c.y)));
}

void MaxDensityGrid::mark(const Cell& cell, const glm::vec2& densities) {
    glm::vec2& value = marked_[cell];
    value = glm::max(value, densities);
}

void MaxDensityGrid::add(int chart, const glm::dvec2& centre, const glm::dvec2& edge_a, const glm::dvec2& edge_b,
                         const glm::dvec2& densities) {
    const glm::dmat2 edges(edge_a, edge_b);
    const double area = std::abs(glm::determinant(edges));
    if (!(area > 0.0) || !std::isfinite(area) || !glm::all(glm::greaterThanEqual(densities, glm::dvec2(0.0))) ||
        !std::isfinite(densities.x + densities.y))
        return;
    const int level = int(std::ceil(std::log2(1.0 / std::sqrt(area))));  // cells at most the footprint's square root
    const double side = std::ldexp(1.0, -level);
    const glm::dmat2 to_ab = glm::inverse(edges);  // (a, b) of a point relative to the centre
    const glm::dvec2 reach = 0.5 * (glm::abs(edge_a) + glm::abs(edge_b));
    const CellRange rows = centres_within(centre.y - reach.y, centre.y + reach.y, side);
    for (std::int64_t row = rows.first; row <= rows.last; ++row) {
        const double y = (double(row) + 0.5) * side;
        double lo = -reach.x, hi = reach.x;
        if (!clip_to_parallelogram(to_ab[1] * (y - centre.y), to_ab[0], lo, hi)) continue;
        const CellRange columns = centres_within(centre.x + lo, centre.x + hi, side);
        for (std::int64_t column = columns.first; column <= columns.last; ++column)
            mark({.chart = chart, .level = level, .x = column, .y = row}, glm::vec2(densities));
    }
}

glm::dvec2 MaxDensityGrid::integral_under(const Cell& cell, const glm::dvec2& inherited,
                                          const std::unordered_set<Cell, CellHash>& inner) const {
    const auto found = marked_.find(cell);
    const glm::dvec2 value = found == marked_.end() ? inherited : glm::max(inherited, glm::dvec2(found->second));
    if (!inner.contains(cell)) return value * std::ldexp(1.0, -2 * cell.level);
    glm::dvec2 sum(0.0);
    for (std::int64_t dy : {0, 1})
        for (std::int64_t dx : {0, 1})
            sum += integral_under(
                {.chart = cell.chart, .level = cell.level + 1, .x = 2 * cell.x + dx, .y = 2 * cell.y + dy}, value,
                inner);
    return sum;
}

glm::dvec2 MaxDensityGrid::integral() const {
    std::map<int, int> coarsest;  // per chart, its coarsest marked level: the quadtree's roots
    for (const auto& [cell, value] : marked_) {
        const auto [at, inserted] = coarsest.try_emplace(cell.chart, cell.level);
        at->second = std::min(at->second, cell.level);
    }
    std::unordered_set<Cell, CellHash> inner;  // cells with a marked cell below them
    inner.reserve(marked_.size());
    for (const auto& [cell, value] : marked_)
        for (Cell up = cell; up.level > coarsest.at(cell.chart);) {
            up = up.parent();
            if (!inner.insert(up).second) break;  // and so are its ancestors
        }
    std::unordered_set<Cell, CellHash> roots;
    for (const auto& [cell, value] : marked_)
        if (cell.level == coarsest.at(cell.chart)) roots.insert(cell);
    for (const Cell& cell : inner)
        if (cell.level == coarsest.at(cell.chart)) roots.insert(cell);
    glm::dvec2 sum(0.0);
    for (const Cell& root : roots) sum += integral_under(root, glm::dvec2(0.0), inner);
    return sum;
}

}  // namespace shadowlab
