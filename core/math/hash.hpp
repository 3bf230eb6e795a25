#pragma once
// A 32-bit integer hash (Wellons' lowbias32): bits that look random and repeat exactly, for jitter
// and per-pixel turns. GLSL's uint arithmetic wraps as C++'s does, so a shader can repeat it.
#include <cstdint>

namespace shadowlab {

inline std::uint32_t lowbias32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

}  // namespace shadowlab
