#pragma once
// The one table of ShadowLab's limits: the scene loader, the CLI and the window check against these
// and no other numbers (README, "Limits"). Beyond a limit, a message names it and the value given.
#include <cstdint>
#include <stdexcept>
#include <string>

namespace shadowlab::limits {

struct Range {
    std::int64_t min, max;
    const char* what;  // "map resolution (texels per side)"
};

// The shadow-map texture: every map of a setup has its tile in it. 16384 is the largest 2D texture
// OpenGL implementations commonly allow (Mesa's llvmpipe included); its CPU copy takes 1 GiB.
inline constexpr Range map_resolution{1, 16384, "map resolution (texels per side)"};
// A camera image: measured, rendered, judged by a technique. Smaller than 16 pixels, VTK's
// offscreen windows misbehave; 8192 keeps a float reference image under 1 GiB.
inline constexpr Range image_side{16, 8192, "image size (pixels per side)"};
// Objects in a scene file, and triangles of all objects once tessellated (meshes included).
inline constexpr Range scene_objects{1, 100'000, "objects in a scene"};
inline constexpr Range scene_triangles{1, 20'000'000, "triangles in a scene"};

inline bool within(const Range& range, std::int64_t value) { return value >= range.min && value <= range.max; }

// "<name>: <value> is outside <min>..<max> (<what>)"
inline std::string outside(const Range& range, const std::string& name, std::int64_t value) {
    return name + ": " + std::to_string(value) + " is outside " + std::to_string(range.min) + ".." +
           std::to_string(range.max) + " (" + range.what + ")";
}

// Throws std::invalid_argument with outside(...) unless the value is within the range.
inline void check(const Range& range, const std::string& name, std::int64_t value) {
    if (!within(range, value)) throw std::invalid_argument(outside(range, name, value));
}

}  // namespace shadowlab::limits
