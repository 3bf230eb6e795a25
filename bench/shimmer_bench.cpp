// What a shimmer run costs against the measures it replaces: 60 frames of a sideways camera path
// on the default scene at 640x360 (the method's maps built and rasterized per frame, every fixed
// point judged), and one `measure` of the same method, resolution and image (the bound: the
// run at most 60 measures). Cascades with visible depth bounds trace a depth image every frame.
#include <benchmark/benchmark.h>

#include <map>
#include <string>

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

using SettingTexts = std::map<std::string, std::string>;

void shimmer_run(benchmark::State& state, const std::string& method_name, const SettingTexts& set) {
    const MeasureContext& c = default_context();
    const Method& method = method_or_throw(method_name);
    const Settings settings = resolve_settings(method.name, method.settings, set);
    const std::vector<ShimmerSample> samples = shimmer_samples(c);
    const CameraPath path{CameraPath::Kind::translate, kFrames, 0.0};
    for (auto _ : state)
        benchmark::DoNotOptimize(measure_shimmer(c, samples, method, settings, kResolution, -1.0, path));
}

void single_measure(benchmark::State& state, const std::string& method_name, const SettingTexts& set) {
    const MeasureContext& c = default_context();
    const Method& method = method_or_throw(method_name);
    const Settings settings = resolve_settings(method.name, method.settings, set);
    for (auto _ : state) benchmark::DoNotOptimize(measure(c, method, settings, kResolution, -1.0));
}

}  // namespace

const SettingTexts kVisibleBounds{{"bounds", "visible"}};

BENCHMARK_CAPTURE(shimmer_run, focused_60_frames, "focused", {})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(single_measure, focused, "focused", {})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(shimmer_run, cascades_60_frames, "cascades", {})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(single_measure, cascades, "cascades", {})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(shimmer_run, cascades_visible_60_frames, "cascades", kVisibleBounds)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(single_measure, cascades_visible, "cascades", kVisibleBounds)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
