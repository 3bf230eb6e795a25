#include "methods/cascade_atlas.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "math/matrix.hpp"

namespace shadowlab {
namespace {

// The Z-order curve's cell `index`: its bits alternate column, row (bit 0 to the column).
glm::ivec2 z_order_cell(long index) {
    glm::ivec2 cell{0, 0};
    for (int bit = 0; index != 0; ++bit, index >>= 2) {
        cell.x |= int(index & 1) << bit;
        cell.y |= int((index >> 1) & 1) << bit;
    }
    return cell;
}

}  // namespace

std::vector<AtlasTile> atlas_layout(int count, const std::vector<double>& relative_sides) {
    std::vector<double> relative = relative_sides.empty() ? std::vector<double>(count, 1.0) : relative_sides;
    const double largest = *std::max_element(relative.begin(), relative.end());
    for (double& r : relative) r /= largest;
    // The largest side: halved until the areas sum to at most the texture's.
    const double area =
        std::accumulate(relative.begin(), relative.end(), 0.0, [](double sum, double r) { return sum + r * r; });
    double largest_side = 1.0;
    while (area * largest_side * largest_side > 1.0) largest_side /= 2;

    std::vector<int> order(count);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return relative[a] > relative[b]; });
    // Buddy placement: the cursor counts the area used in the smallest tile's cells; every tile so far
    // is at least as large as the next, so the cursor sits on a multiple of the next tile's area.
    const double smallest = largest_side * *std::min_element(relative.begin(), relative.end());
    std::vector<AtlasTile> tiles(count);
    long cursor = 0;
    for (int i : order) {
        const double side = largest_side * relative[i];
        const long cells_per_side = std::lround(side / smallest);
        const glm::ivec2 cell = z_order_cell(cursor / (cells_per_side * cells_per_side));
        tiles[i] = {.column = cell.x, .row = cell.y, .side = side};
        cursor += cells_per_side * cells_per_side;
    }
    return tiles;
}

glm::dvec4 tile_viewport(const AtlasTile& tile) {
    const double u0 = tile.side * tile.column, v1 = 1.0 - tile.side * tile.row;  // rows count down from the top
    return {u0, v1 - tile.side, u0 + tile.side, v1};
}

glm::dmat4 atlas_tile_matrix(const AtlasTile& tile) {
    const double half = tile.side / 2;
    return from_rows({half, 0, 0, half + tile.side * tile.column}, {0, -half, 0, half + tile.side * tile.row},
                     {0, 0, 1, 0}, {0, 0, 0, 1});
}

}  // namespace shadowlab
