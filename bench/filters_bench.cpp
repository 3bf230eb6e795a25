// Each filter's CPU cost per pixel against the hard lookup's: the default scene under a sun of
// angular radius 0.5°, the focused map at 2048², every receiver pixel of a 640x360 image looked up
// once per iteration on one thread (pixels per second: the counter; the ratio to `hard` in the same
// run is the cost of the filter). VSM and EVSM: the moments' blur once per map, outside the
// per-pixel timing, benchmarked on its own.
#include <benchmark/benchmark.h>

#include "lookup/shadow_reader.hpp"
#include "metrics/measurement.hpp"
#include "registry/method.hpp"
#include "scene/scene_loader.hpp"

using namespace shadowlab;

namespace {

constexpr int kWidth = 640, kHeight = 360, kResolution = 2048;

struct FilterScene {
    Scene scene;
    ShadowSetup setup;
    DepthMap depth;
    std::vector<Receiver> receivers;
};

ShadowLookup lookup_with(const std::map<std::string, std::string>& overrides) {
    const Method& focused = method_or_throw("focused");
    return lookup_from(resolve_settings("focused", focused.settings, overrides));
}

const FilterScene& filter_scene() {
    static const FilterScene s = [] {
        FilterScene f;
        f.scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/default.json");
        f.scene.light.angular_radius_deg = 0.5;
        const Method& focused = method_or_throw("focused");
        f.setup =
            focused.compute_maps(gather_inputs(f.scene), resolve_settings("focused", focused.settings, {}), nullptr);
        const WorldTriangles triangles = tessellate(f.scene);
        f.depth = rasterize_depth(triangles, caster_flags(f.scene), f.setup, kResolution, lookup_with({}).format);
        const ReferenceImage ref = exact_reference(f.scene, triangles, kWidth, kHeight);
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x)
                if (const size_t i = size_t(y) * kWidth + x; ref.visible[i] && ref.facing[i] > 0.0f)
                    f.receivers.push_back({ref.position[i], ref.normal[i], pixel_rotation(x, y)});
        return f;
    }();
    return s;
}

void lookups(benchmark::State& state, const std::map<std::string, std::string>& overrides) {
    const FilterScene& s = filter_scene();
    const ShadowReader reader(s.setup, s.depth, s.scene.light, lookup_with(overrides));
    LookupCount count;
    for (auto _ : state) {
        double sum = 0.0;
        for (const Receiver& r : s.receivers) sum += reader.visibility(r, &count);
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(s.receivers.size()));
    state.counters["taps_per_pixel"] = double(count.taps) / double(state.iterations() * s.receivers.size());
}

void moments_blur(benchmark::State& state, const std::map<std::string, std::string>& overrides) {
    const FilterScene& s = filter_scene();
    const ShadowFilter filter = lookup_with(overrides).filter;
    for (auto _ : state) benchmark::DoNotOptimize(blurred_moments(s.depth, s.setup, filter).moments.data());
}

}  // namespace

BENCHMARK_CAPTURE(lookups, hard, {})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lookups, pcf_box_3, {{"filter", "pcf"}})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lookups, pcf_tent_3, {{"filter", "pcf"}, {"pcf_kernel", "tent"}})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lookups, pcf_poisson_4, {{"filter", "pcf"}, {"pcf_kernel", "poisson"}, {"kernel_size", "4"}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lookups, pcss_4, {{"filter", "pcss"}, {"kernel_size", "4"}})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lookups, vsm, {{"filter", "vsm"}})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lookups, evsm, {{"filter", "evsm"}})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lookups, receiver_plane, {{"bias_receiver_plane", "on"}})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(moments_blur, vsm_3, {{"filter", "vsm"}})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(moments_blur, evsm_3, {{"filter", "evsm"}})->Unit(benchmark::kMillisecond);
