#pragma once
// Texels per unit of view depth along the view axis as a chart (the window's Plot dock and
// `lesson`): the method's against the ideal density, at which the perspective factor of m is 1
// (core/flatland/texel_density.hpp), both axes logarithmic, where the ideal is a line of slope −1.
#include <string>
#include <vector>

#include "flatland/texel_density.hpp"
#include "plot/chart_png.hpp"

namespace shadowlab {

ChartSpec density_chart(const std::vector<DensitySample>& samples, const std::string& method, int resolution,
                        int image_height);

}  // namespace shadowlab
