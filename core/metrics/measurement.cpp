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
    const Stopwatch raster_watch;
    const DepthMap depth = rasterize_depth(c.triangles, c.casters, setup, resolution);
    m.raster_ms = raster_watch.ms();
    m.lookup = lookup_from(settings, bias);
    const ShadowReader reader(setup, depth, c.scene.light, m.lookup);
    m.prefilter_ms = reader.prefilter_ms();
    LookupCount count;
    const Stopwatch lookup_watch;
    const std::vector<float> visibility = receiver_visibility(c.scene, c.reference, reader, &count);
    m.lookup_ms = lookup_watch.ms();
    m.error = measure_shadow_error(c.scene, c.reference, reader, visibility);
    m.taps_per_pixel = m.error.receiver_pixels ? double(count.taps) / double(m.error.receiver_pixels) : 0.0;
    for (Note& note : reader.fallbacks(count)) m.fallbacks.push_back(std::move(note));
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

MeasureContext prepare_measurement(const Scene& scene, int width, int height, int light_samples) {
    MeasureContext c{scene, object_boxes(scene), tessellate(scene), caster_flags(scene), {}};
    const glm::ivec2 image = image_size_within(scene.camera, width, height);
    c.reference = light_reference(scene, c.triangles, image.x, image.y, light_samples);
    return c;
}

Measurement measure(const MeasureContext& c, const Method& method, const Settings& settings, int resolution,
                    double bias) {
    return method.makes_maps() ? measure_maps(c, method, settings, resolution, bias)
                               : measure_geometry(c, method, settings);
}

}  // namespace shadowlab
