#include "measure_command.hpp"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <stdexcept>

#include "io/inspection_json.hpp"
#include "metrics/shadow_error.hpp"
#include "scene/scene_loader.hpp"
#include "scene/tessellation.hpp"

namespace shadowlab {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Long work says what it is doing on stderr, so that stdout stays the result.
template <class Work>
auto step(const char* what, Work&& work) {
    std::cerr << "measure: " << what << "..." << std::flush;
    const Clock::time_point start = Clock::now();
    auto result = work();
    std::cerr << " " << ms_since(start) << " ms\n";
    return result;
}

// The fastest of a few runs: a setup takes microseconds and this machine is noisy.
double setup_ms(const Method& method, const Scene& scene, const std::vector<ObjectBox>& boxes, const Settings& settings) {
    double best = INFINITY;
    for (int run = 0; run < 5; ++run) {
        const Clock::time_point start = Clock::now();
        const ShadowSetup setup = method.compute(gather_inputs(scene.camera, scene.light, boxes), settings, nullptr);
        best = std::min(best, ms_since(start));
        (void)setup;
    }
    return best;
}

void print(const MeasureOptions& o, const ShadowSetup& setup, const ShadowError& e, double setup_time, double raster_time,
           double bias) {
    Json j{{"method", o.method},
           {"resolution", o.resolution},
           {"misclassified", e.misclassified},
           {"false_shadow", e.false_shadow},
           {"false_light", e.false_light},
           {"m", {{"max", e.m.max}, {"mean", e.m.mean}, {"p95", e.m.p95}}},
           {"setup_ms", setup_time},
           {"raster_ms", raster_time},
           {"fallback", setup.fallback ? Json(*setup.fallback) : Json(nullptr)},
           {"bias", bias},
           {"receiver_pixels", e.receiver_pixels}};
    if (o.json) {
        std::cout << j.dump(1) << "\n";
        return;
    }
    std::cout << "method " << o.method << " at " << o.resolution << "^2, image " << o.width << "x" << o.height
              << ", bias " << bias << "\n"
              << "  misclassified " << 100 * e.misclassified << "% of " << e.receiver_pixels
              << " receiver pixels (false shadow " << 100 * e.false_shadow << "%, false light " << 100 * e.false_light
              << "%)\n"
              << "  m (texel extent in pixels): max " << e.m.max << ", mean " << e.m.mean << ", p95 " << e.m.p95 << "\n"
              << "  cost: setup " << setup_time << " ms, raster " << raster_time << " ms, total "
              << setup_time + raster_time << " ms\n"
              << "  fallback: " << setup.fallback.value_or("none") << "\n";
}

}  // namespace

void run_measure(const MeasureOptions& o) {
    const Method* method = find_method(o.method);
    if (!method) throw std::invalid_argument("unknown method '" + o.method + "'");
    if (o.resolution < 1 || o.resolution > 16384) throw std::invalid_argument("--resolution: expected 1 to 16384");
    if (o.width < 1 || o.height < 1) throw std::invalid_argument("--size: expected positive WxH");
    const Settings settings = resolve_settings(method->name, method->settings, o.settings);
    const Scene scene = load_scene(o.scene_file);
    const std::vector<ObjectBox> boxes = object_boxes(scene);
    const ShadowInputs inputs = gather_inputs(scene.camera, scene.light, boxes);
    const double bias = o.bias >= 0.0 ? o.bias : 2e-4 * inputs.scene_bounds.diagonal();

    const WorldTriangles triangles = tessellate(scene);
    const ReferenceImage reference = step("exact reference (Embree rays)", [&] {
        return exact_reference(scene, triangles, o.width, o.height);
    });
    const ShadowSetup setup = method->compute(inputs, settings, nullptr);
    const double setup_time = setup_ms(*method, scene, boxes, settings);
    const Clock::time_point raster_start = Clock::now();
    const DepthMap depth = step("rasterizing the map", [&] {
        return rasterize_depth(triangles, caster_flags(scene), setup.maps.at(0), o.resolution);
    });
    const double raster_time = ms_since(raster_start);
    const ShadowError error = step("comparing", [&] {
        return measure_shadow_error(scene, reference, depth, setup.maps.at(0), bias);
    });
    print(o, setup, error, setup_time, raster_time, bias);
}

}  // namespace shadowlab
