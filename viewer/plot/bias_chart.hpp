#pragma once
// A bias sweep as a chart (`shadowlab sweep --bias` and the window's Plot dock): per method, its
// false shadow (acne, a solid line) and false light (peter panning and leaks, dashed, same colour)
// against the swept bias on a log axis, and its best point marked and labelled.
#include <string>
#include <vector>

#include "metrics/bias_sweep.hpp"
#include "plot/chart_png.hpp"

namespace shadowlab {

// A swept value in its unit: "1.41×" (of the slope-scaled bias), "2 texels", "0.354" (world units).
std::string bias_value_text(const std::string& setting, double value);

// One chart of every curve (all of one setting). The log axis cannot show 0: a value of 0 is drawn
// at half the smallest positive value, and the x axis's title says so.
ChartSpec bias_chart(const std::vector<BiasCurve>& curves, const std::string& title);

}  // namespace shadowlab
