#include "plot/density_chart.hpp"

namespace shadowlab {

ChartSpec density_chart(const std::vector<DensitySample>& samples, const std::string& method, int resolution,
                        int image_height) {
    ChartSpec chart{
        .title = method + " at " + std::to_string(resolution) + "²: texels per unit of view depth along the view axis",
        .x_title = "view depth z (world units)",
        .y_title = "texels per unit of view depth",
        .log_x = true,
        .log_y = true};
    ChartSeries texels{.name = method},
        ideal{.name = "ideal: m = 1 on an image " + std::to_string(image_height) + " pixels tall, falling as 1/z",
              .dashed = true};
    for (const DensitySample& s : samples) {
        texels.x.push_back(s.depth), texels.y.push_back(s.texels);
        ideal.x.push_back(s.depth), ideal.y.push_back(s.ideal);
    }
    chart.series = {texels, ideal};
    chart.legend = ChartSpec::LegendCorner::top_right;
    return chart;
}

}  // namespace shadowlab
