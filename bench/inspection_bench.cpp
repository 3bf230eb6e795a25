// What one change in the window costs before drawing: inspect_scene on the default scene (the
// method with its trace, the tessellation and the CPU depth map; for a technique its verdicts on
// a 640-wide camera image).
#include <benchmark/benchmark.h>

#include "model/inspection.hpp"
#include "scene/scene_loader.hpp"

using namespace shadowlab;

namespace {

void inspection(benchmark::State& state, const std::string& scene_file, const std::string& method) {
    const Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/" + scene_file);
    InspectionRequest request;
    request.method = method;
    request.resolution = static_cast<int>(state.range(0));
    for (auto _ : state) benchmark::DoNotOptimize(inspect_scene(scene, request));
}

}  // namespace

BENCHMARK_CAPTURE(inspection, default_focused, "default.json", "focused")->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(inspection, default_lispsm, "default.json", "lispsm")->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(inspection, volumes_zfail, "volumes.json", "volumes")->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();
