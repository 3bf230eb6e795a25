#pragma once
// XY charts written to PNG files, rendered offscreen with VTK's chart classes (no VTK types here).
#include <array>
#include <string>
#include <vector>

namespace shadowlab {

struct ChartSeries {
    std::string name;                             // the legend entry
    std::vector<double> x, y;                     // same length
    std::vector<std::string> labels;              // optional: one text per point, drawn beside it
    bool line = true;                             // points joined by a line (else points only)
    std::vector<bool> marked;                     // optional: per point, also drawn with a cross (e.g. fallbacks)
    std::array<unsigned char, 3> color{0, 0, 0};  // RGB; {0, 0, 0} picks from a palette by series index
    bool dashed = false;    // the line drawn dashed (a second quantity of the same subject, same colour)
    bool in_legend = true;  // false: no legend entry (a mark that annotates another series)
};

struct ChartSpec {
    std::string title, x_title, y_title;
    bool log_x = false, log_y = false;  // points with a non-positive value on a log axis are dropped
    int width = 900, height = 600;
    std::vector<ChartSeries> series;
    enum class LegendCorner { top_right, top_left, bottom_left, bottom_right };
    LegendCorner legend = LegendCorner::top_right;  // where the legend box sits: away from the points
};

// The palette's colour number `index` (cycling through ten).
std::array<unsigned char, 3> palette_color(size_t index);

// The colour series `index` is drawn with: its own, or the palette's when it is {0, 0, 0}.
std::array<unsigned char, 3> series_color(const ChartSpec& chart, size_t index);

// Renders the chart offscreen (one colour per series, a legend) and writes it as a PNG. Throws
// std::runtime_error when no X display can be opened ("plots need an X display: run under
// xvfb-run"), when a series is malformed, or when the file cannot be written.
void write_chart_png(const ChartSpec& chart, const std::string& png_file);

}  // namespace shadowlab
