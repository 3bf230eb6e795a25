#include "gui/plot_measure.hpp"

#include <algorithm>
#include <stdexcept>

#include "metrics/bias_sweep.hpp"
#include "metrics/measurement.hpp"
#include "model/inspection.hpp"
#include "plot/density_chart.hpp"
#include "plot/bias_chart.hpp"
#include "plot/shimmer_chart.hpp"
#include "registry/method.hpp"

namespace shadowlab {
namespace {

ChartSpec error_against_resolution(const MeasureContext& context, const Method& method, const Settings& settings) {
    ChartSpec chart;
    chart.title = method.name + ": error against map resolution";
    chart.x_title = "map resolution (texels per side)";
    chart.y_title = "misclassified % / max perspective m (px)";
    chart.log_x = chart.log_y = true;
    ChartSeries wrong{"misclassified %", {}, {}, {}, true, {}, {}};
    // The perspective factor of m: the part a parameterization (and its resolution) controls; m's
    // own max is set by faces edge-on to the light, whatever the map.
    ChartSeries m{"max perspective m (texel width in pixels)", {}, {}, {}, true, {}, {}};
    for (int resolution : {256, 512, 1024, 2048}) {
        const Measurement r = measure(context, method, settings, resolution, -1.0);
        wrong.x.push_back(resolution), wrong.y.push_back(std::max(1e-3, 100.0 * r.error.misclassified));
        m.x.push_back(resolution), m.y.push_back(std::max(1e-3, r.error.m_perspective.max));
    }
    chart.series = {wrong, m};
    return chart;
}

// The window's other settings held, bias_slope swept.
ChartSpec acne_against_bias(const MeasureContext& context, const Method& method,
                            std::map<std::string, std::string> settings, int resolution) {
    settings.erase("bias_slope");
    const BiasCurve curve = sweep_bias(context, method, settings, resolution, "bias_slope",
                                       default_bias_values(context, "bias_slope", resolution));
    ChartSpec chart = bias_chart({curve}, method.name + " at " + std::to_string(resolution) +
                                              "²: acne (false shadow) solid, false light dashed");
    chart.y_title = "% of receiver pixels";
    return chart;
}

// The method's map at the window's resolution, no reference traced: its density along the view
// against the ideal of an image as tall as the map is wide (H = R: as many pixels as texels).
ChartSpec density_along_view(const PlotRequest& request) {
    const Inspection in = inspect_scene(
        request.scene, {.method = request.method, .settings = request.settings, .resolution = request.resolution});
    return density_chart(texel_density_over_view(in.inputs, in.setup, in.resolution, in.resolution), in.name(),
                         in.resolution, in.resolution);
}

}  // namespace

std::string plot_work(const PlotRequest& request) {
    switch (request.kind) {
        case PlotKind::shimmer:
            return "plot: " + request.method + " along " + std::to_string(kShimmerFrames) +
                   " frames of a sideways camera path";
        case PlotKind::acne_against_bias:
            return "plot: measuring " + request.method +
                   " at 0 and 1/16 to 32 times the slope-scaled bias against the exact reference";
        case PlotKind::density_along_view:
            return "plot: " + request.method + "'s texels per unit of view depth along the view axis";
        case PlotKind::error_against_resolution: break;
    }
    return "plot: measuring " + request.method + " at 256² to 2048² against the exact reference";
}

Plot measure_plot(const PlotRequest& request) {
    const Method& method = method_or_throw(request.method);
    if (!method.makes_maps()) throw std::invalid_argument("plot: " + method.name + " makes no shadow map");
    Plot plot;
    if (request.kind == PlotKind::density_along_view) {
        plot.chart = density_along_view(request);
        plot.chart.width = 520;
        plot.chart.height = 320;
        return plot;
    }
    const MeasureContext context = prepare_measurement(request.scene, kPlotImageWidth, kPlotImageWidth);
    const Settings settings = resolve_settings(method.name, method.settings, request.settings);
    if (request.kind == PlotKind::shimmer) {
        const CameraPath path{CameraPath::Kind::translate, kShimmerFrames, 0.0};
        plot.shimmer =
            measure_shimmer(context, shimmer_samples(context), method, settings, request.resolution, -1.0, path);
        plot.chart = shimmer_chart(*plot.shimmer, method.name + " at " + std::to_string(request.resolution) +
                                                      "²: " + shimmer_summary(*plot.shimmer));
    } else if (request.kind == PlotKind::acne_against_bias) {
        plot.chart = acne_against_bias(context, method, request.settings, request.resolution);
    } else {
        plot.chart = error_against_resolution(context, method, settings);
    }
    plot.chart.width = 520;
    plot.chart.height = 320;
    return plot;
}

}  // namespace shadowlab
