#pragma once
// The one table of ShadowLab's limits: the scene loader, the CLI and the window check against these
// and no other numbers (README, "Limits"). Beyond a limit, a message names it and the value given.
#include <cstdint>
#include <sstream>
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
// Objects in a scene file, and the triangles of its meshes (each mesh object counted).
inline constexpr Range scene_objects{1, 100'000, "objects in a scene"};
inline constexpr Range scene_triangles{1, 20'000'000, "triangles in a scene"};

// The real-valued fields of a scene file (README, "Scene format"). Together they keep every
// computation downstream finite, in double and in Embree's float32: a world coordinate stays
// within ±1e12 and an object's smallest extent (a length times a scale) above 1e-12, so that a
// product of three (a cross product's component, a determinant) stays within 1e-36 … 1e36, inside
// float32's normal range (1.2e-38 … 3.4e38). Directions and up vectors may be any finite non-zero
// vector (math/normalize.hpp scales before it squares), rotations any finite angle.
struct RealRange {
    double min, max;
    bool open = false;  // the ends themselves excluded
};

// Positions (camera, target, lights, objects) and every corner of a placed object.
inline constexpr RealRange coordinate{-1e12, 1e12};
// Sizes, radii, heights, and the camera's near and far distances.
inline constexpr RealRange length{1e-6, 1e12};
// Each component of an object's scale.
inline constexpr RealRange scale{1e-6, 1e6};
// The camera's aspect (width / height): beyond 1000 : 1 an image is a line of pixels.
inline constexpr RealRange aspect{1e-3, 1e3};
// The camera's vertical field of view and a spot light's cone (full apex angle), in degrees.
inline constexpr RealRange angle_deg{0.0, 180.0, true};
// The camera's far / near: the depth range a map's depth and the float32 tracer resolve.
inline constexpr double far_over_near_max = 1e9;

inline bool within(const Range& range, std::int64_t value) { return value >= range.min && value <= range.max; }
inline bool within(const RealRange& range, double value) {
    return range.open ? value > range.min && value < range.max : value >= range.min && value <= range.max;
}

// A table entry as messages and the README write it: 1e12, 1e-6, 0.001, 180.
inline std::string shown(double value) {
    std::ostringstream out;
    out << value;  // 1e+12, 1e-06
    std::string text = out.str();
    const std::size_t e = text.find('e');
    if (e == std::string::npos) return text;
    std::size_t digits = e + 1;
    if (text[digits] == '+') text.erase(digits, 1);
    if (text[digits] == '-') ++digits;
    while (text[digits] == '0' && digits + 1 < text.size()) text.erase(digits, 1);
    return text;
}

// "±1e12", "[0.001, 1000]", "(0, 180)".
inline std::string shown(const RealRange& range) {
    // Appended, not prefixed: GCC 12 warns falsely of overlap (-Wrestrict) in `"±" + std::string`.
    if (!range.open && range.min == -range.max) return std::string("±").append(shown(range.max));
    return std::string(range.open ? "(" : "[")
        .append(shown(range.min))
        .append(", ")
        .append(shown(range.max))
        .append(range.open ? ")" : "]");
}

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
