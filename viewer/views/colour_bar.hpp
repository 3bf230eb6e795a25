#pragma once
// A colour bar: the legend of a quantity painted on a continuous ramp (the Error view's m, its
// signed visibility error, the Shadow map view's moments), hung from the view's top-left corner.
#include <functional>
#include <string>
#include <vector>

#include "views/view_parts.hpp"

class vtkRenderer;

namespace shadowlab {

struct ColourBar {
    std::function<Rgb(double)> ramp;  // the colour at t in [0, 1] along the bar, left to right
    std::vector<std::string> ticks;   // under the bar, evenly spaced from its left end to its right end
    std::string low_side, high_side;  // above its left and right ends: what each side means (two lines)
    std::string title;                // on the legend's first row; empty: none (the view has its own legend)
};

void add_colour_bar(vtkRenderer* renderer, const ColourBar& bar);

}  // namespace shadowlab
