#pragma once
// An engine's clip space against ShadowLab's map space. An engine's light view-projection takes a
// world point to clip space (x, y, z, w): x / w and y / w in [-1, 1], z / w in its API's depth
// range, the texture's v running with y or against it. ShadowLab's world_to_uvz wants (u w, v w,
// d w, w) with u, v, d in [0, 1] and d growing away from the light; one matrix joins the two.
#include <glm/glm.hpp>

namespace shadowlab {

enum class ClipDepth {
    minus_one_to_one,  // OpenGL: z / w = -1 at the near plane, 1 at the far
    zero_to_one,       // Direct3D, Vulkan, Metal: z / w = 0 at the near plane, 1 at the far
};

enum class TextureV {
    up,    // v = (1 + y) / 2: OpenGL, and Vulkan, whose framebuffer y and texture v both run down
    down,  // v = (1 - y) / 2: Direct3D, whose clip y runs up and texture v down
};

struct ClipConventions {
    ClipDepth depth = ClipDepth::minus_one_to_one;
    bool reversed_z = false;  // z / w = 1 at the near plane (the far plane at 0, or -1)
    TextureV v = TextureV::up;
};

// The matrix taking an engine's clip space to ShadowLab's (u w, v w, d w, w): world_to_uvz =
// uvz_from_clip(conventions) * clip_from_world, with (u, v) the engine's own texture coordinates.
glm::dmat4 uvz_from_clip(const ClipConventions& conventions);

}  // namespace shadowlab
