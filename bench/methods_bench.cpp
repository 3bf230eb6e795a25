// Method setup time (inputs gathered per view + the method), for every map method of the registry
// (default settings at three town sizes, traced, and each other choice of its choice settings), and
// the intersection body per kernel.
#include <benchmark/benchmark.h>

#include <map>
#include <random>

#include "geometry/intersection_body.hpp"
#include "reference/visible_depths.hpp"
#include "registry/method.hpp"
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

constexpr glm::ivec2 kDepthImage{640, 360};

void method_setup(benchmark::State& state, const Method* method, const std::map<std::string, std::string>& set,
                  bool traced) {
    const Scene scene = town(int(state.range(0)));
    const std::vector<ObjectBox> boxes = object_boxes(scene);
    const Settings settings = resolve_settings(method->name, method->settings, set);
    // Visible depth bounds read the camera's depth image: traced once, as a renderer's depth pre-pass.
    ShadowInputs seen;
    if (method->wants_visible_depths(settings))
        trace_depth_image(seen, scene, tessellate(scene), kDepthImage.x, kDepthImage.y);
    for (auto _ : state) {
        ShadowInputs inputs = gather_inputs(scene.camera, scene.light, boxes);
        inputs.visible_depths = seen.visible_depths;
        inputs.seen_receivers = seen.seen_receivers;
        Trace trace;
        ShadowSetup setup = method->compute_maps(inputs, settings, traced ? &trace : nullptr);
        benchmark::DoNotOptimize(setup);
    }
}

// method_setup/<name>, <name>_traced and <name>_<choice> for every map method.
const bool registered = [] {
    for (const Method& m : all_methods()) {
        if (!m.makes_maps()) continue;
        const std::string name = "method_setup/" + m.name;
        benchmark::RegisterBenchmark(name.c_str(), method_setup, &m, std::map<std::string, std::string>{}, false)
            ->Arg(10)
            ->Arg(1000)
            ->Arg(10000)
            ->Unit(benchmark::kMicrosecond);
        benchmark::RegisterBenchmark((name + "_traced").c_str(), method_setup, &m, std::map<std::string, std::string>{},
                                     true)
            ->Arg(1000)
            ->Unit(benchmark::kMicrosecond);
        for (const SettingSpec& spec : m.settings)
            for (const std::string& choice : spec.choices)
                if (choice != spec.default_value)
                    benchmark::RegisterBenchmark((name + "_" + choice).c_str(), method_setup, &m,
                                                 std::map<std::string, std::string>{{spec.name, choice}}, false)
                        ->Arg(1000)
                        ->Unit(benchmark::kMicrosecond);
    }
    return true;
}();

void body(benchmark::State& state, BodyKernel kernel) {
    const Scene scene = town(1000);
    const std::vector<ObjectBox> boxes = object_boxes(scene);
    const ShadowInputs in = gather_inputs(scene.camera, scene.light, boxes);
    const BodyInput input{in.frustum, in.scene_bounds, in.light.homogeneous()};
    for (auto _ : state) benchmark::DoNotOptimize(intersection_body(input, kernel));
}

}  // namespace

BENCHMARK_CAPTURE(body, float_clipper, BodyKernel::float_clipper)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(body, epick, BodyKernel::epick)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(body, epeck, BodyKernel::epeck)->Unit(benchmark::kMicrosecond);
