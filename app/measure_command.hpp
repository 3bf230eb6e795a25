#pragma once
// `shadowlab measure SCENE --method M --resolution N [--size WxH] [--bias B] [--set k=v]... [--json]`
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "exchange/inspection_json.hpp"
#include "metrics/diagnosis.hpp"
#include "metrics/measurement.hpp"
#include "plot/chart_png.hpp"
#include "scene_source.hpp"

namespace shadowlab {

struct MeasureOptions {
    std::string scene_file;
    SceneSource scene_source;  // which of the scene file's cameras and lights, or an engine's camera
    std::string method = "focused";
    std::map<std::string, std::string> settings;
    int resolution = 1024;
    int width = 1280, height = 720;
    double bias = -1.0;  // world units along the light; < 0: slope-scaled per pixel
    bool json = false;
};

// What `measure` reports: the measurement and the diagnosis of its misclassified pixels.
struct MeasureRun {
    Measurement measurement;
    std::optional<Diagnosis> diagnosis;  // when asked: each cause's remedy is measured too
};

// The method of `options` (its name, settings, resolution and bias; not its scene or size) measured
// on `context`, and diagnosed when asked, remedies named on stderr; throws on bad input. The Python
// module's measure is this call.
MeasureRun measure_on(const MeasureContext& context, const MeasureOptions& options, bool diagnose = true);
// `measure --json`'s object ("diagnosis" only when diagnosed).
Json to_json(const MeasureRun& run, const MeasureContext& context);

// Prints the metrics to stdout and progress to stderr; throws on bad input.
void run_measure(const MeasureOptions& options);

// Shared with `bench` and `sweep`. A technique's JSON has the map keys (resolution 0, m and
// depth_step 0: no texels; bias and depth_format null) and "polygons", "fill_mean", "fill_max"; "fallback" is the
// fallbacks as one line (null for none), "fallbacks" and "limits" list them by kind.
Json to_json(const Measurement& measurement);
// measure's "diagnosis": {"misclassified_pixels", "causes": [{"kind", "pixels", "share", "remedy":
// {"change", "removes", "adds", "misclassified"} or null}]}, most pixels first.
Json to_json(const Diagnosis& diagnosis);
// The named methods, or every method of the registry when `names` is empty.
std::vector<const Method*> methods_named(const std::vector<std::string>& names);
MeasureContext prepare_with_progress(const std::string& scene_file, const SceneSource& source, int width, int height);
// The same for a loaded scene, named on stderr by `label`.
MeasureContext prepare_with_progress(const Scene& scene, const std::string& label, int width, int height);
// One plotted point of a measurement: misclassified share in %, marked when a fallback was taken
// (a map) or a limit met (a technique).
void add_error_point(ChartSeries& series, double x, const Measurement& measurement);

}  // namespace shadowlab
