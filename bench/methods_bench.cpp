// Method setup time (inputs gathered per view + the method), and the intersection body per kernel.
#include <benchmark/benchmark.h>

#include <random>

#include "geometry/intersection_body.hpp"
#include "methods/method.hpp"
#include "scene/scene.hpp"

using namespace shadowlab;

namespace {

// The default scene's shape: a town of `count` boxes on a 400-unit ground, camera near the ground.
Scene town(int count) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(-190.0, 190.0), h(2.0, 40.0), w(2.0, 10.0);
    Scene scene;
    SceneObject ground;
    ground.shape = Shape::plane;
    ground.size = {400, 1, 400};
    scene.objects.push_back(ground);
    for (int i = 0; i < count; ++i) {
        SceneObject box;
        box.size = {w(rng), h(rng), w(rng)};
        box.position = {u(rng), box.size.y / 2, u(rng)};
        box.rotation_deg = {0, u(rng), 0};
        scene.objects.push_back(box);
    }
    scene.camera.position = {0, 2.5, 180};
    scene.camera.target = {0, 2.0, 0};
    scene.camera.near = 0.5;
    scene.camera.far = 400;
    scene.light.direction = glm::normalize(glm::dvec3(-0.6, -0.3, -0.7));
    return scene;
}

void method_setup(benchmark::State& state, const std::string& name, const std::string& kernel, bool traced) {
    const Scene scene = town(int(state.range(0)));
    const std::vector<ObjectBox> boxes = object_boxes(scene);
    const Method& method = *find_method(name);
    std::map<std::string, std::string> set;
    if (!kernel.empty()) set["kernel"] = kernel;
    const Settings settings = resolve_settings(name, method.settings, set);
    for (auto _ : state) {
        const ShadowInputs inputs = gather_inputs(scene.camera, scene.light, boxes);
        Trace trace;
        ShadowSetup setup = method.compute(inputs, settings, traced ? &trace : nullptr);
        benchmark::DoNotOptimize(setup);
    }
}

void body(benchmark::State& state, BodyKernel kernel) {
    const Scene scene = town(1000);
    const std::vector<ObjectBox> boxes = object_boxes(scene);
    const ShadowInputs in = gather_inputs(scene.camera, scene.light, boxes);
    const BodyInput input{in.frustum, in.scene_bounds, in.light.homogeneous()};
    for (auto _ : state) benchmark::DoNotOptimize(intersection_body(input, kernel));
}

}  // namespace

BENCHMARK_CAPTURE(method_setup, uniform, "uniform", "", false)->Arg(10)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(method_setup, focused_float, "focused", "float", false)->Arg(10)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(method_setup, focused_float_traced, "focused", "float", true)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(method_setup, focused_epick, "focused", "epick", false)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(method_setup, focused_epeck, "focused", "epeck", false)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(method_setup, psm, "psm", "float", false)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(method_setup, lispsm, "lispsm", "float", false)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(method_setup, tsm, "tsm", "float", false)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(method_setup, xpsm, "xpsm", "float", false)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(method_setup, xpsm_traced, "xpsm", "float", true)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(body, float_clipper, BodyKernel::float_clipper)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(body, epick, BodyKernel::epick)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(body, epeck, BodyKernel::epeck)->Unit(benchmark::kMicrosecond);
