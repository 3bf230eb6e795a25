// Stencil shadow volumes on the CPU: building the volume (edge topology, silhouette, extrusion and
// caps), the stencil count alone (the volume rasterized at the pixel centres), and the whole
// technique (the volume plus the count) on a 640x360 camera image. The count is our stand-in for
// the GPU's stencil passes, not their cost.
#include <benchmark/benchmark.h>

#include "reference/exact_shadows.hpp"
#include "registry/method.hpp"
#include "scene/scene_loader.hpp"
#include "volumes/edge_topology.hpp"
#include "volumes/shadow_volume.hpp"
#include "volumes/silhouette.hpp"
#include "volumes/stencil_count.hpp"

using namespace shadowlab;

namespace {

Scene scene_named(const std::string& name) {
    Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/" + name + ".json");
    scene.camera.aspect = 640.0 / 360.0;
    return scene;
}

void volume_build(benchmark::State& state, const std::string& name) {
    const Scene scene = scene_named(name);
    const WorldTriangles triangles = tessellate(scene);
    size_t polygons = 0;
    for (auto _ : state) {
        const ShadowVolume volume =
            extrude_volume(find_silhouette(caster_topology(scene, triangles), triangles, scene.light), scene.light);
        polygons = volume.quads.size();
        benchmark::DoNotOptimize(polygons);
    }
    state.counters["triangles"] = static_cast<double>(triangles.triangles.size());
    state.counters["quads"] = static_cast<double>(polygons);
}

void volume_stencil_count(benchmark::State& state, const std::string& name, CountRule rule) {
    const Scene scene = scene_named(name);
    const WorldTriangles triangles = tessellate(scene);
    const ReferenceImage image = exact_reference(scene, triangles, 640, 360);
    const ShadowVolume volume =
        extrude_volume(find_silhouette(caster_topology(scene, triangles), triangles, scene.light), scene.light);
    for (auto _ : state) benchmark::DoNotOptimize(count_stencil(volume, scene.camera, image, rule));
}

void volumes_technique(benchmark::State& state, const std::string& name, const std::string& count) {
    const Scene scene = scene_named(name);
    const WorldTriangles triangles = tessellate(scene);
    const ReferenceImage image = exact_reference(scene, triangles, 640, 360);
    const Method& volumes = *find_method("volumes");
    const Settings settings = resolve_settings("volumes", volumes.settings, {{"count", count}});
    for (auto _ : state) benchmark::DoNotOptimize(volumes.compute_geometry(scene, triangles, image, settings, nullptr));
}

}  // namespace

BENCHMARK_CAPTURE(volume_build, volumes, "volumes")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(volume_build, default, "default")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(volume_stencil_count, volumes_zfail, "volumes", CountRule::zfail)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(volume_stencil_count, default_zpass, "default", CountRule::zpass)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(volume_stencil_count, default_zfail, "default", CountRule::zfail)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(volumes_technique, volumes_zfail, "volumes", "zfail")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(volumes_technique, volumes_zpass, "volumes", "zpass")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(volumes_technique, default_zfail, "default", "zfail")->Unit(benchmark::kMillisecond)->UseRealTime();
