#pragma once
// `shadowlab measure SCENE --method M --resolution N [--size WxH] [--bias B] [--set k=v]... [--json]`
#include <map>
#include <string>
#include <vector>

#include "io/inspection_json.hpp"
#include "metrics/measurement.hpp"
#include "plot/chart_png.hpp"

namespace shadowlab {

struct MeasureOptions {
    std::string scene_file;
    std::string method = "focused";
    std::map<std::string, std::string> settings;
    int resolution = 1024;
    int width = 1280, height = 720;
    double bias = -1.0;  // world units along the light; < 0: slope-scaled per pixel
    bool json = false;
};

// Prints the metrics to stdout and progress to stderr; throws on bad input.
void run_measure(const MeasureOptions& options);

// Shared with `bench` and `sweep`.
Json to_json(const Measurement& measurement);
const Method& method_named(const std::string& name);
// The named methods, or every method when `names` is empty.
std::vector<const Method*> methods_named(const std::vector<std::string>& names);
MeasureContext prepare_with_progress(const std::string& scene_file, int width, int height);
void check_resolution(int resolution);
// One plotted point of a measurement: misclassified share in %, marked when a fallback was taken.
void add_error_point(ChartSeries& series, double x, const Measurement& measurement);

}  // namespace shadowlab
