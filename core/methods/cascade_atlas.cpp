#include "methods/cascade_atlas.hpp"

#include "math/matrix.hpp"

namespace shadowlab {

AtlasTile atlas_tile(int index, int count) {
    int columns = 1;
    while (columns * columns < count) columns *= 2;
    return {.column = index % columns, .row = index / columns, .side = 1.0 / columns};
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
