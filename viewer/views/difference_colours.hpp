#pragma once
// The Difference view's colours, one per class of metrics/verdict_comparison.hpp, named so that
// tests can look for them. Where the two verdicts differ, orange and blue (told apart by colour-blind
// readers too) say which configuration is right; pixels no configuration judges keep the Error
// view's greys (error_colours.hpp).
#include <array>

namespace shadowlab::difference_colours {

using Colour = std::array<unsigned char, 3>;

inline constexpr Colour kBothRight{200, 200, 205};  // light grey: nothing to see
inline constexpr Colour kBothWrong{120, 30, 110};   // dark purple: neither configuration helps here
inline constexpr Colour kOnlyARight{240, 140, 0};   // orange: A right, B wrong
inline constexpr Colour kOnlyBRight{0, 120, 240};   // blue: B right, A wrong

}  // namespace shadowlab::difference_colours
