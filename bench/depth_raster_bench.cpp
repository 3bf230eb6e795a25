// The CPU depth rasterizer alone (rasterize_depth, on every core), for every map method of the
// registry on the default scene at 2048²: the part of a change the Shadow map, Texels and Error views
// wait for (issue 16); and the focused map in every depth format (raster/depth_format.hpp). The setup
// and triangles are made once, outside the timing.
#include <map>
#include <string>
#include <benchmark/benchmark.h>

#include "model/inspection.hpp"
#include "scene/scene_loader.hpp"

using namespace shadowlab;

namespace {

constexpr int kResolution = 2048;

void depth_raster(benchmark::State& state, const std::string& method,
                  const std::map<std::string, std::string>& settings) {
    const Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/default.json");
    InspectionRequest request;
    request.method = method;
    request.settings = settings;
    request.resolution = kResolution;
    const Inspection in = inspect_scene(scene, request);
    for (auto _ : state) {
        const DepthMap depth = rasterize_depth(in.triangles, in.casters, in.setup, kResolution, in.lookup.format);
        benchmark::DoNotOptimize(depth.codes.data());
    }
}

// One benchmark per map method, named after it.
const bool kRegistered = [] {
    for (const Method& m : all_methods())
        if (m.makes_maps())
            benchmark::RegisterBenchmark(("depth_raster/" + m.name).c_str(), depth_raster, m.name,
                                         std::map<std::string, std::string>{})
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime();
    for (const DepthFormat& format : depth_formats())
        benchmark::RegisterBenchmark(("depth_raster_format/focused/" + describe(format)).c_str(), depth_raster,
                                     "focused", depth_format_settings(format))
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    return true;
}();

}  // namespace
