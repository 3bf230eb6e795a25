#pragma once
// How a shadow map stores its depth: the encoding of a depth buffer (16- or 24-bit unsigned
// normalized, 32-bit float) and whether the depth is reversed (stored as s = 1 − d, the far plane at
// 0). The precision a map resolves near a depth d sets how far apart a caster and a receiver must
// lie to be told apart: a 16-bit map, or float32 near its far end, turns into acne where the bias
// is too small for its step. Reversed Z puts float32's dense levels near 0 at the far end, where a
// perspective map crowds its depths (Reed 2015, "Depth Precision Visualized"; Lapidous and Jiao
// 1999, "Optimal depth buffer for low-cost graphics hardware").
#include <algorithm>
#include <bit>
#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab {

enum class DepthEncoding { unorm16, unorm24, float32 };
const char* to_string(DepthEncoding encoding);  // "unorm16", "unorm24", "float32"
// Every encoding, the default (float32) first: the choices of the depth_format setting.
std::vector<DepthEncoding> depth_encodings();

struct DepthFormat {
    DepthEncoding encoding = DepthEncoding::float32;
    bool reversed = false;  // stores s = 1 − d: nearest is the greatest value, the far plane 0

    bool operator==(const DepthFormat&) const = default;
};
// Every format: each encoding (depth_encodings' order) plain, then reversed.
std::vector<DepthFormat> depth_formats();

// "unorm16", "float32 reversed", ...
std::string describe(const DepthFormat& format);

// d in [0, 1] as the format stores it, read back as d: the nearest level of the encoding to s (s = d,
// or 1 − d reversed), clamped to [0, 1] (plain float32 keeps depths beyond 1, as rasterize_depth does).
double stored_depth(const DepthFormat& format, double depth);

// The gap between adjacent stored levels at d, in units of d: 1 / (2^N − 1) for an N-bit unorm
// anywhere; for float32 the spacing of floats at s (their ulp; below s where s is 1, the top of the
// range), so reversed it shrinks toward d = 1 as plain float32's does toward d = 0.
double depth_step(const DepthFormat& format, double depth);

// ---- The texel codes a DepthMap holds (raster/depth_map.hpp) ----

// One texel of a depth map: an N-bit unorm's level k (s = k / (2^N − 1)), or float32's bits of s. Both
// are ordered as the values they stand for (non-negative floats order as their bits), so that the
// rasterizer keeps the nearest by comparing codes: the least plain, the greatest reversed.
using DepthCode = std::uint32_t;

// The number of steps between 0 and 1 of an N-bit unorm, 2^N − 1 (0 for float32).
constexpr double unorm_levels(DepthEncoding encoding) {
    return encoding == DepthEncoding::unorm16 ? 65535.0 : encoding == DepthEncoding::unorm24 ? 16777215.0 : 0.0;
}

// The code of a stored value s (the format's own, 1 − d when reversed), clamped to [0, 1] (to
// [0, ∞) for plain float32, which keeps casters beyond the far plane as they are); NaN as 0. For a
// loop that knows its format when it is compiled (the rasterizer's); depth_code below for any.
// float32 is rounded before it is clamped, so that the loop vectorizes; a unorm rounds to the
// nearest level, as OpenGL converts a depth to fixed point.
template <DepthEncoding encoding, bool reversed>
DepthCode code_of(double stored) {
    if constexpr (encoding == DepthEncoding::float32) {
        const float at_least_0 = std::max(0.0f, static_cast<float>(stored));
        return std::bit_cast<DepthCode>(reversed ? std::min(1.0f, at_least_0) : at_least_0);
    } else {
        const double clamped = std::min(1.0, std::max(0.0, stored));
        return static_cast<DepthCode>(static_cast<std::int32_t>(clamped * unorm_levels(encoding) + 0.5));
    }
}
DepthCode depth_code(const DepthFormat& format, double stored);

// A code read back as d, exactly in double: d = s, or 1 − s reversed (a float holding 1 − s would
// lose what reversed Z gains near d = 1). Branch-free but for the encoding's kind: what every
// reader's texel read costs (DepthMap::at).
class DepthDecoder {
public:
    constexpr explicit DepthDecoder(const DepthFormat& format)
        : is_float_(format.encoding == DepthEncoding::float32),
          per_level_(is_float_ ? 0.0 : 1.0 / unorm_levels(format.encoding)),
          offset_(format.reversed ? 1.0 : 0.0),
          sign_(format.reversed ? -1.0 : 1.0) {}

    double operator()(DepthCode code) const {
        const double s = is_float_ ? double(std::bit_cast<float>(code)) : double(code) * per_level_;
        return offset_ + sign_ * s;
    }

private:
    bool is_float_;
    double per_level_;      // unorm: 1 / (2^N − 1)
    double offset_, sign_;  // d = offset + sign s: (0, 1) plain, (1, −1) reversed
};

// The value the format stores for d, before its encoding rounds it: s = d, or 1 − d reversed.
inline double format_value(const DepthFormat& format, double depth) { return format.reversed ? 1.0 - depth : depth; }

// The code nothing was drawn in: the far plane (d = 1).
inline DepthCode far_code(const DepthFormat& format) { return depth_code(format, format_value(format, 1.0)); }

}  // namespace shadowlab
