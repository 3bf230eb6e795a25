#pragma once
// What the Plot dock shows, measured: for one method on the exact reference of a small camera
// image, its error and aliasing against map resolution, its shimmer while the camera moves
// sideways (the same measure as `shadowlab shimmer`), or its acne and peter panning against the
// slope-scaled bias's scale (as `shadowlab sweep --bias` draws them), or its texels per unit of
// view depth along the view axis against the ideal (core/flatland/texel_density.hpp). No Qt, no drawing: the
// window's worker measures it off the GUI thread (gui/background_inspection.hpp) and the dock draws it.
#include <map>
#include <optional>
#include <string>

#include "metrics/shimmer.hpp"
#include "plot/chart_png.hpp"
#include "scene/scene.hpp"

namespace shadowlab {

enum class PlotKind { error_against_resolution, shimmer, acne_against_bias, density_along_view };

// The shimmer plot's path and image: `shadowlab shimmer SCENE --frames 30 --size 320x320` measures the same.
constexpr int kShimmerFrames = 30, kPlotImageWidth = 320;

struct PlotRequest {
    PlotKind kind = PlotKind::error_against_resolution;
    Scene scene;
    std::string method;                           // a map method of the registry
    std::map<std::string, std::string> settings;  // the window's, as text
    int resolution = 1024;                        // shimmer, bias and density: the map's; error: 256² to 2048²
};

struct Plot {
    ChartSpec chart;
    std::optional<Shimmer> shimmer;  // the shimmer plot's measure
};

// What measure_plot will measure, for the window's progress line.
std::string plot_work(const PlotRequest& request);
// Throws std::invalid_argument for a method without a map, or settings it refuses.
Plot measure_plot(const PlotRequest& request);

}  // namespace shadowlab
