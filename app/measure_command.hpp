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

// A shadow-map method or a geometric technique (shadow volumes, planar projection): every command
// takes either by name.
struct NamedMethod {
    const Method* map = nullptr;
    const Technique* technique = nullptr;

    const std::string& name() const { return map ? map->name : technique->name; }
    const std::vector<SettingSpec>& settings() const { return map ? map->settings : technique->settings; }
};

// Shared with `bench` and `sweep`. A technique's JSON has the map keys (resolution 0, m and
// depth_step 0: no texels; bias null) and "polygons", "fill_mean", "fill_max".
Json to_json(const Measurement& measurement);
NamedMethod method_named(const std::string& name);
// The named methods, or every map method then every technique when `names` is empty.
std::vector<NamedMethod> methods_named(const std::vector<std::string>& names);
// A map at `resolution` with `bias`; a technique ignores both.
Measurement measure_named(const MeasureContext& context, const NamedMethod& method, const Settings& settings,
                          int resolution, double bias);
MeasureContext prepare_with_progress(const std::string& scene_file, int width, int height);
void check_resolution(int resolution);
// One plotted point of a measurement: misclassified share in %, marked when a fallback was taken.
void add_error_point(ChartSeries& series, double x, const Measurement& measurement);

}  // namespace shadowlab
