// What the storage lower bound (metrics/storage_bound.hpp) adds to a measure context (`add_storage_bounds`): the
// bound over the default scene's reference at 640x360 and 1280x720, beside the exact reference it
// is computed from (the Embree rays `prepare_measurement` traces first).
#include <benchmark/benchmark.h>

#include <string>

#include "metrics/storage_bound.hpp"
#include "scene/scene_loader.hpp"
#include "scene/tessellation.hpp"

using namespace shadowlab;

namespace {

const Scene& default_scene() {
    static const Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/default.json");
    return scene;
}

void exact_reference_of(benchmark::State& state) {
    const WorldTriangles triangles = tessellate(default_scene());
    for (auto _ : state)
        benchmark::DoNotOptimize(exact_reference(default_scene(), triangles, int(state.range(0)), int(state.range(1))));
}

void storage_bounds_of(benchmark::State& state) {
    const ReferenceImage reference =
        exact_reference(default_scene(), tessellate(default_scene()), int(state.range(0)), int(state.range(1)));
    for (auto _ : state) benchmark::DoNotOptimize(storage_lower_bounds(default_scene(), reference));
}

}  // namespace

BENCHMARK(exact_reference_of)->Args({640, 360})->Args({1280, 720})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(storage_bounds_of)->Args({640, 360})->Args({1280, 720})->Unit(benchmark::kMillisecond)->UseRealTime();
