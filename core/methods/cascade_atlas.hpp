#pragma once
// All cascades in one texture: square tiles in a grid, read left to right from the top (four in
// 2 x 2, as the usual Direct3D atlas of cascaded shadow maps). The tile side is 1 / 2^k of the texture, so that a power-of-two texture
// puts every tile edge on a texel boundary (the GPU pass draws whole texels; map_lookup.hpp).
#include <glm/glm.hpp>

namespace shadowlab {

constexpr int kMaxCascades = 8;  // a 4 x 2 grid of quarter-side tiles; a tile of 1 texel is not knowable here

struct AtlasTile {
    int column = 0, row = 0;  // row 0 at the top of the texture
    double side = 1.0;        // the tile's side as a share of the texture's
};

// Tile `index` of `count` (1..kMaxCascades): the smallest power-of-two grid side that holds them.
AtlasTile atlas_tile(int index, int count);

// The tile as ShadowMap::viewport (u0, v0, u1, v1), v growing up as in our textures.
glm::dvec4 tile_viewport(const AtlasTile& tile);

// The tile matrix of a Direct3D atlas lookup: the map's NDC (x, y in [-1, 1], y up) onto the texture's (u, v) with v down
// (Direct3D): scale x by side / 2, y by -side / 2, offset side / 2 + side * (column, row): for 2 x 2,
// x by 1/4, y by -1/4, offset 1/4 + 1/2 tile.
glm::dmat4 atlas_tile_matrix(const AtlasTile& tile);

}  // namespace shadowlab
