#pragma once
// The linear projection kinds: a 4x4 world_to_uvz, world (x, y, z, 1) -> (u w, v w, d_pre, w), for
// orthographic, perspective and warped maps; and a cube face, one 90° face of a cube map, the same
// mapping with its face (0..5 for +x, -x, +y, -y, +z, -z) for the selection rule cube_face. Both are
// projective: straight lines stay straight, so the rasterizer clips to the unit cube and w > 0 alone.
#include "maps/projection_kind.hpp"

namespace shadowlab {

extern const ProjectionKind linear_projection;
extern const ProjectionKind cube_face_projection;

}  // namespace shadowlab
