// What a shimmer run costs against the measures it replaces: 60 frames of a sideways camera path
// on the default scene at 640x360 (the method's maps built and rasterized per frame, every fixed
// point judged), and one `measure` of the same method, resolution and image (the bound: the
// run at most 60 measures).
#include <benchmark/benchmark.h>

#include "metrics/shimmer.hpp"
#include "scene/scene_loader.hpp"

using namespace shadowlab;

namespace {

constexpr int kFrames = 60, kResolution = 1024;

const MeasureContext& default_context() {
    static const MeasureContext context =
        prepare_measurement(load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/default.json"), 640, 360);
    return context;
}

Settings defaults(const Method& method) { return resolve_settings(method.name, method.settings, {}); }

void shimmer_run(benchmark::State& state, const std::string& method_name) {
    const MeasureContext& c = default_context();
    const Method& method = method_or_throw(method_name);
    const std::vector<ShimmerSample> samples = shimmer_samples(c);
    const CameraPath path{CameraPath::Kind::translate, kFrames, 0.0};
    for (auto _ : state)
        benchmark::DoNotOptimize(measure_shimmer(c, samples, method, defaults(method), kResolution, -1.0, path));
}

void single_measure(benchmark::State& state, const std::string& method_name) {
    const MeasureContext& c = default_context();
    const Method& method = method_or_throw(method_name);
    for (auto _ : state) benchmark::DoNotOptimize(measure(c, method, defaults(method), kResolution, -1.0));
}

}  // namespace

BENCHMARK_CAPTURE(shimmer_run, focused_60_frames, "focused")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(single_measure, focused, "focused")->Unit(benchmark::kMillisecond)->UseRealTime();
