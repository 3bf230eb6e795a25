// The soft reference's throughput: the default scene under a sun of angular radius 0.5°, 640x360,
// 64 stratified shadow rays per visible pixel on both cores (issue 15's bound: >= 10 M rays/s).
// The primary rays and the BVH builds are inside the timing, as a user waits for them.
#include <benchmark/benchmark.h>

#include "reference/exact_shadows.hpp"
#include "scene/scene_loader.hpp"

using namespace shadowlab;

namespace {

constexpr int kWidth = 640, kHeight = 360, kSamples = 64;

void soft_reference_rays(benchmark::State& state) {
    Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/default.json");
    scene.light.angular_radius_deg = 0.5;
    const WorldTriangles triangles = tessellate(scene);
    size_t rays = 0;
    for (auto _ : state) {
        const ReferenceImage soft = soft_reference(scene, triangles, kWidth, kHeight, kSamples);
        for (uint8_t visible : soft.visible) rays += visible ? size_t(soft.light_samples) : 0;
        benchmark::DoNotOptimize(soft.visibility.data());
    }
    state.counters["shadow_rays_per_s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK(soft_reference_rays)->Unit(benchmark::kMillisecond)->UseRealTime();
