#pragma once
// All cascades in one texture: square tiles whose sides are powers-of-two shares of the texture
// (four equal ones in 2 x 2, as the usual Direct3D atlas of cascaded shadow maps; or a large near
// cascade beside smaller far ones: the resolution per cascade). A power-of-two texture then puts
// every tile edge on a texel boundary (the GPU pass draws whole texels; map_lookup.hpp).
#include <vector>
#include <glm/glm.hpp>

namespace shadowlab {

constexpr int kMaxCascades = 8;

// The smallest tile: 1/8 of the texture's side (256 texels of a 2048² atlas, so the snap grid's
// 256 cells per tile are still whole texels; cascade_fit.hpp).
constexpr double kMinTileSide = 1.0 / 8;

struct AtlasTile {
    int column = 0, row = 0;  // in tiles of this side; row 0 at the top of the texture
    double side = 1.0;        // the tile's side as a share of the texture's
};

// The tiles of `count` cascades (1..kMaxCascades) whose sides relate as `relative_sides` (one per
// cascade, each 1, 1/2, 1/4 or 1/8 of the largest; empty: all equal). The largest side is the
// largest power-of-two share of the texture at which all fit; the tiles are placed largest first
// along the Z-order curve, as a quadtree's buddy allocator does: squares of power-of-two sides so
// placed never overlap and fill the texture without gaps, so they fit whenever their areas sum to
// at most 1. Tiles may come out smaller than kMinTileSide: the caller refuses those.
std::vector<AtlasTile> atlas_layout(int count, const std::vector<double>& relative_sides);

// The tile as ShadowMap::viewport (u0, v0, u1, v1), v growing up as in our textures.
glm::dvec4 tile_viewport(const AtlasTile& tile);

// The tile matrix of a Direct3D atlas lookup: the map's NDC (x, y in [-1, 1], y up) onto the texture's (u, v) with v
// down (Direct3D): scale x by side / 2, y by -side / 2, offset side / 2 + side * (column, row): for 2 x 2, x by 1/4, y
// by -1/4, offset 1/4 + 1/2 tile.
glm::dmat4 atlas_tile_matrix(const AtlasTile& tile);

}  // namespace shadowlab
