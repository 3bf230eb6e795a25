#include "plot/shimmer_chart.hpp"

#include <cstdio>

namespace shadowlab {
namespace {

double percent(size_t part, size_t whole) { return whole ? 100.0 * part / whole : 0.0; }

}  // namespace

ChartSpec shimmer_chart(const Shimmer& s, const std::string& title) {
    ChartSpec chart{title, "frame", "share of the fixed points (%)", false, false, 900, 600, {}};
    ChartSeries flipped{.name = "verdict flipped since the frame before"}, wrong{.name = "verdict wrong"};
    for (const FrameShimmer& f : s.frames) {
        wrong.x.push_back(f.frame), wrong.y.push_back(percent(f.wrong, f.judged));
        if (f.frame == 0) continue;  // nothing before it to flip from
        flipped.x.push_back(f.frame), flipped.y.push_back(percent(f.flips, f.transitions));
    }
    chart.series = {flipped, wrong};
    return chart;
}

std::string shimmer_summary(const Shimmer& s) {
    char text[96];
    std::snprintf(text, sizeof text, "%.4f %% of %zu transitions flipped", 100.0 * s.share(), s.transitions());
    return text;
}

}  // namespace shadowlab
