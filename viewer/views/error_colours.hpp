#pragma once
// The Error view's fixed colours, named so that tests can look for them. None is in the heat map's
// inferno-like ramp (black, purple, red, orange, pale yellow): misclassified pixels are blue and
// green, the background a neutral mid grey.
#include <array>

namespace shadowlab::error_colours {

using Colour = std::array<unsigned char, 3>;

inline constexpr Colour kFalseShadow{0, 150, 255};  // acne: shadowed, but the reference says lit
inline constexpr Colour kFalseLight{0, 255, 0};     // a leak: lit, but the reference says shadowed
inline constexpr Colour kNotVisible{128, 128, 128}; // no surface (the sky): the background
inline constexpr Colour kNotJudged{84, 84, 90};     // a visible surface that receives no shadow
inline constexpr Colour kAgreeLit{215, 215, 220};   // a technique's agreeing pixels (it has no texels)
inline constexpr Colour kAgreeShadowed{52, 52, 60};

}  // namespace shadowlab::error_colours
