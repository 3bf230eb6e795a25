// What one change in the window costs before drawing, on the default scene at 2048²: inspect_scene
// (the method with its trace, the tessellation; for a technique its verdicts on a 640-wide camera
// image), for every method of the registry; and for the map methods the same with the CPU depth map
// the Shadow map, Texels and Error views read (rasterized on every core, only when read).
#include <benchmark/benchmark.h>

#include "model/inspection.hpp"
#include "scene/scene_loader.hpp"

using namespace shadowlab;

namespace {

const Scene& default_scene() {
    static const Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/default.json");
    return scene;
}

void inspection(benchmark::State& state, const std::string& method, bool with_depth_map) {
    InspectionRequest request;
    request.method = method;
    request.resolution = 2048;
    for (auto _ : state) {
        const Inspection in = inspect_scene(default_scene(), request);
        if (with_depth_map) benchmark::DoNotOptimize(in.depth().codes.data());
        benchmark::DoNotOptimize(in);
    }
}

// One benchmark per method (and per map method one with its depth map), named after it.
const bool kRegistered = [] {
    for (const Method& m : all_methods()) {
        benchmark::RegisterBenchmark(("inspection/" + m.name).c_str(), inspection, m.name, false)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        if (m.makes_maps())
            benchmark::RegisterBenchmark(("inspection_with_depth_map/" + m.name).c_str(), inspection, m.name, true)
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime();
    }
    return true;
}();

}  // namespace
