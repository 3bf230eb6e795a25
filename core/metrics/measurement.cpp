#include "metrics/measurement.hpp"

#include <algorithm>
#include <cmath>

#include "math/stopwatch.hpp"
#include "reference/visible_depths.hpp"
#include "scene/image_size.hpp"

namespace shadowlab {
namespace {

// The setup, and the fastest of a few runs of it: a setup takes microseconds and the machine is noisy.
// The visible depths, when the settings read them, are reduced from the reference's camera image
// (its depth image) inside the timed run.
ShadowSetup timed_setup(const MeasureContext& c, const Method& method, const Settings& settings, double& best_ms) {
    ShadowSetup setup;
    best_ms = INFINITY;
    for (int run = 0; run < 5; ++run) {
        const Stopwatch watch;
        ShadowInputs inputs = gather_inputs(c.scene.camera, c.scene.light, c.boxes);
        if (method.wants_visible_depths(settings)) inputs.visible_depths = receiver_depth_range(c.scene, c.reference);
        setup = method.compute_maps(inputs, settings, nullptr);
        best_ms = std::min(best_ms, watch.ms());
    }
    return setup;
}

Measurement measure_maps(const MeasureContext& c, const Method& method, const Settings& settings, int resolution,
                         double bias) {
    Measurement m;
    m.method = method.name;
    m.resolution = resolution;
    m.bias = bias;
    const ShadowSetup setup = timed_setup(c, method, settings, m.setup_ms);
    m.fallbacks = setup.fallbacks;
    for (const ShadowMap& map : setup.maps) m.texels_used += std::pow(tile_resolution(map, resolution), 2);
    const Stopwatch watch;
    const DepthMap depth = rasterize_depth(c.triangles, c.casters, setup, resolution);
    m.raster_ms = watch.ms();
    m.error = measure_shadow_error(c.scene, c.reference, depth, setup, m.bias);
    if (setup.maps.size() > 1) m.by_map = break_down_by_map(c.reference, m.error, setup);
    return m;
}

Measurement measure_geometry(const MeasureContext& c, const Method& method, const Settings& settings) {
    const GeometryResult result = method.compute_geometry(c.scene, c.triangles, c.reference, settings, nullptr);
    Measurement m;
    m.method = method.name;
    m.error = judge_shadows(c.scene, c.reference, result.shadowed);
    m.setup_ms = result.setup_ms;
    m.raster_ms = result.raster_ms;
    m.limits = result.limits;
    m.geometry = result.cost;
    return m;
}

}  // namespace

MeasureContext prepare_measurement(const Scene& scene, int width, int height) {
    MeasureContext c{scene, object_boxes(scene), tessellate(scene), caster_flags(scene), {}};
    const glm::ivec2 image = image_size_within(scene.camera, width, height);
    c.reference = exact_reference(scene, c.triangles, image.x, image.y);
    return c;
}

Measurement measure(const MeasureContext& c, const Method& method, const Settings& settings, int resolution,
                    double bias) {
    return method.makes_maps() ? measure_maps(c, method, settings, resolution, bias)
                               : measure_geometry(c, method, settings);
}

}  // namespace shadowlab
