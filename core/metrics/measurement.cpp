#include "metrics/measurement.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace shadowlab {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The setup, and the fastest of a few runs of it: a setup takes microseconds and the machine is noisy.
ShadowSetup timed_setup(const MeasureContext& c, const Method& method, const Settings& settings, double& best_ms) {
    ShadowSetup setup;
    best_ms = INFINITY;
    for (int run = 0; run < 5; ++run) {
        const Clock::time_point start = Clock::now();
        setup = method.compute(gather_inputs(c.scene.camera, c.scene.light, c.boxes), settings, nullptr);
        best_ms = std::min(best_ms, ms_since(start));
    }
    return setup;
}

}  // namespace

MeasureContext prepare_measurement(const Scene& scene, int width, int height) {
    MeasureContext c{scene, object_boxes(scene), tessellate(scene), caster_flags(scene), {}};
    c.reference = exact_reference(scene, c.triangles, width, height);
    return c;
}

Measurement measure_method(const MeasureContext& c, const Method& method, const Settings& settings, int resolution,
                           double bias) {
    Measurement m;
    m.method = method.name;
    m.resolution = resolution;
    m.bias = bias;
    const ShadowSetup setup = timed_setup(c, method, settings, m.setup_ms);
    m.fallback = setup.fallback;
    const Clock::time_point start = Clock::now();
    const DepthMap depth = rasterize_depth(c.triangles, c.casters, setup.maps.at(0), resolution);
    m.raster_ms = ms_since(start);
    m.error = measure_shadow_error(c.scene, c.reference, depth, setup.maps.at(0), m.bias);
    return m;
}

}  // namespace shadowlab
