#include "plot/bias_chart.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "io/value_text.hpp"

namespace shadowlab {

std::string bias_value_text(const std::string& setting, double value) {
    const std::string number = significant(value, 3);
    if (setting == "bias_slope") return number + "×";
    if (setting == "bias_normal") return number + (value == 1.0 ? " texel" : " texels");
    return number;
}

namespace {

// A share drawn on the chart's log axis: none (0) at the floor, below one pixel of 1e5.
constexpr double kBiasChartFloorPercent = 1e-3;

// The swept setting and its unit, for an axis.
std::string bias_axis_text(const std::string& setting) {
    if (setting == "bias_slope") return "bias_slope (times the slope-scaled bias)";
    if (setting == "bias_normal") return "bias_normal (texel widths along the surface normal)";
    return setting + " (world units along the light)";
}

// "best: 1.41× gives 0.31 %" (VTK's chart font has no arrow)
std::string best_point_text(const BiasCurve& curve) {
    const BiasPoint& best = curve.points.at(curve.best);
    return "best: " + bias_value_text(curve.setting, best.value) + " gives " +
           significant(100.0 * best.misclassified, 2) + " %";
}

}  // namespace

ChartSpec bias_chart(const std::vector<BiasCurve>& curves, const std::string& title) {
    double smallest = INFINITY;
    for (const BiasCurve& curve : curves)
        for (const BiasPoint& p : curve.points)
            if (p.value > 0.0) smallest = std::min(smallest, p.value);
    const double zero_x = std::isfinite(smallest) ? smallest / 2 : 1.0;
    const std::string setting = curves.empty() ? std::string("bias") : curves.front().setting;
    ChartSpec chart{.title = title,
                    .x_title = bias_axis_text(setting) + "   (0 drawn at " + significant(zero_x, 3) + ")",
                    .y_title = "% of receiver pixels: false shadow (acne) solid, false light dashed",
                    .log_x = true,
                    .log_y = true};
    auto percent = [](double share) { return std::max(kBiasChartFloorPercent, 100.0 * share); };
    for (size_t k = 0; k < curves.size(); ++k) {
        const BiasCurve& curve = curves[k];
        const std::array<unsigned char, 3> color = palette_color(k);  // one colour per method, all three series
        // One legend entry per method: the y axis's title tells its solid line from its dashed one.
        ChartSeries acne{.name = curve.method, .color = color},
            light{.name = curve.method + ": false light", .color = color, .dashed = true, .in_legend = false};
        for (const BiasPoint& p : curve.points) {
            const double x = p.value > 0.0 ? p.value : zero_x;
            acne.x.push_back(x), acne.y.push_back(percent(p.false_shadow)), acne.marked.push_back(!p.fallbacks.empty());
            light.x.push_back(x), light.y.push_back(percent(p.false_light));
        }
        const BiasPoint& best = curve.points.at(curve.best);
        ChartSeries mark{.name = curve.method + ": best",
                         .x = {best.value > 0.0 ? best.value : zero_x},
                         .y = {percent(best.misclassified)},
                         .labels = {best_point_text(curve)},
                         .line = false,
                         .color = color,
                         .in_legend = false};
        chart.series.insert(chart.series.end(), {acne, light, mark});
    }
    return chart;
}

}  // namespace shadowlab
