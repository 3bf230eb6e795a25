#pragma once
// The shimmer measure as a chart: per frame, the share of the fixed points whose verdict flipped
// since the frame before, and the share judged wrong (`shadowlab shimmer` and the window's Plot dock).
#include <string>

#include "metrics/shimmer.hpp"
#include "plot/chart_png.hpp"

namespace shadowlab {

ChartSpec shimmer_chart(const Shimmer& shimmer, const std::string& title);

// "0.1234 % of 56789 transitions flipped"
std::string shimmer_summary(const Shimmer& shimmer);

}  // namespace shadowlab
