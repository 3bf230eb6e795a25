#pragma once
// The Error view's fixed colours, named so that tests can look for them. None is in the heat map's
// inferno-like ramp (black, purple, red, orange, pale yellow): misclassified pixels are blue and
// green, the background a neutral mid grey. The signed visibility error has its own diverging ramp,
// blue through white to red, shown alone (no verdicts, no heat map beside it).
#include <algorithm>
#include <array>
#include <cmath>

namespace shadowlab::error_colours {

using Colour = std::array<unsigned char, 3>;

inline constexpr Colour kFalseShadow{0, 150, 255};   // acne: shadowed, but the reference says lit
inline constexpr Colour kFalseLight{0, 255, 0};      // a leak: lit, but the reference says shadowed
inline constexpr Colour kNotVisible{128, 128, 128};  // no surface (the sky): the background
inline constexpr Colour kNotJudged{84, 84, 90};      // a visible surface that receives no shadow
inline constexpr Colour kAgreeLit{215, 215, 220};    // a technique's agreeing pixels (it has no texels)
inline constexpr Colour kAgreeShadowed{52, 52, 60};

// The signed visibility error, method − reference, over [−1, 1], the whole range a visibility in
// [0, 1] allows, so that a colour means the same error in every picture. The ends of ColorBrewer's
// RdBu: a colour-blind reader still tells them apart by lightness.
inline constexpr Colour kTooDark{33, 102, 172};  // −1: the method shadows what the reference lights
inline constexpr Colour kExact{247, 247, 247};   //  0
inline constexpr Colour kTooLight{178, 24, 43};  // +1: the method lights what the reference shadows

inline Colour signed_error_colour(double error) {
    const double t = std::clamp(std::abs(error), 0.0, 1.0);
    const Colour& end = error < 0.0 ? kTooDark : kTooLight;
    Colour out{};
    for (int c = 0; c < 3; ++c) out[c] = static_cast<unsigned char>(std::lround(kExact[c] + t * (end[c] - kExact[c])));
    return out;
}

}  // namespace shadowlab::error_colours
