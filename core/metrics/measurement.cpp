#include "metrics/measurement.hpp"

#include <algorithm>
#include <cmath>

#include "lookup/lookup_settings.hpp"
#include "maps/map_mask.hpp"
#include "math/stopwatch.hpp"
#include "methods/step_figures.hpp"
#include "methods/warp_common.hpp"
#include "reference/visible_depths.hpp"
#include "scene/image_size.hpp"

namespace shadowlab {
namespace {

// The setup, and the fastest of a few runs of it: a setup takes microseconds and the machine is noisy.
// The visible depths, when the settings read them, are reduced from the reference's camera image
// (its depth image) inside the timed run.
ShadowInputs inputs_for(const MeasureContext& c, const Method& method, const Settings& settings, int resolution) {
    ShadowInputs inputs = gather_inputs(c.scene.camera, c.scene.light, c.boxes);
    inputs.texture_resolution = resolution;
    if (method.wants_visible_depths(settings)) read_depth_image(inputs, c.scene, c.reference);
    return inputs;
}

ShadowSetup timed_setup(const MeasureContext& c, const Method& method, const Settings& settings, int resolution,
                        double& best_ms) {
    ShadowSetup setup;
    best_ms = INFINITY;
    for (int run = 0; run < 5; ++run) {
        const Stopwatch watch;
        setup = method.compute_maps(inputs_for(c, method, settings, resolution), settings, nullptr);
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
    const ShadowSetup setup = timed_setup(c, method, settings, resolution, m.setup_ms);
    m.fallbacks = setup.fallbacks;
    for (const ShadowMap& map : setup.maps)
        m.texels_used += std::pow(tile_resolution(map, resolution), 2) * mask_area(map);
    m.lookup = lookup_from(settings, bias);
    const Stopwatch raster_watch;
    const DepthMap depth = rasterize_depth(c.triangles, c.casters, setup, resolution, m.lookup.format);
    m.raster_ms = raster_watch.ms();
    const ShadowReader reader(setup, depth, c.scene.light, m.lookup);
    m.prefilter_ms = reader.prefilter_ms();
    LookupCount count;
    const Stopwatch lookup_watch;
    const std::vector<float> visibility = receiver_visibility(c.scene, c.reference, reader, &count);
    m.lookup_ms = lookup_watch.ms();
    m.error = measure_shadow_error(c.scene, c.reference, reader, visibility);
    if (c.storage_bounds)
        m.storage = storage_factor(m.texels_used, m.error.m_perspective, c.storage_bounds->for_coverage(method.covers));
    m.taps_per_pixel = m.error.receiver_pixels ? double(count.taps) / double(m.error.receiver_pixels) : 0.0;
    for (Note& note : reader.fallbacks(count)) m.fallbacks.push_back(std::move(note));
    if (setup.maps.size() > 1) m.by_map = break_down_by_map(c.reference, m.error, setup);
    if (setup.selection.rule == MapSelection::Rule::pages) m.pages = setup.selection.pages;
    return m;
}

// A warp loses to the focused map when it misclassifies more than kLossRatio times its share and
// kLossMargin more (0.05 percentage points: a few pixels of a small image are no loss).
constexpr double kLossRatio = 2.0, kLossMargin = 0.0005;

// Texels this many times the focused map's (perspective m, 95th percentile) are coarser, not noise.
constexpr double kCoarser = 1.5;

std::string percent(double share) { return label_number(100.0 * share) + "%"; }

// Why the warp lost: the error it adds (false shadow: acne; false light: leaks and lost shadows), its
// texels against the focused map's where the camera looks, and the depths it chose.
std::string loss_cause(const Measurement& warp, const Measurement& focused, const std::string& choices) {
    const ShadowError &w = warp.error, &f = focused.error;
    const bool acne = w.false_shadow - f.false_shadow > w.false_light - f.false_light;
    std::string text = warp.method + " misclassifies " + percent(w.misclassified) + " against the focused map's " +
                       percent(f.misclassified) + "; mostly " +
                       (acne ? "false shadow (acne: the bias is too small for the warp's depth slope), " +
                                   percent(w.false_shadow) + " against " + percent(f.false_shadow)
                             : "false light (leaks and lost shadows), " + percent(w.false_light) + " against " +
                                   percent(f.false_light)) +
                       "; perspective m p95 " + label_number(w.m_perspective.p95) + " against " +
                       label_number(f.m_perspective.p95) +
                       (w.m_perspective.p95 > kCoarser * f.m_perspective.p95
                            ? " (the warp's texels are coarser where the camera looks)"
                            : "");
    return choices.empty() ? text : text + "; " + choices;
}

// The focused map measured on the same reference (traced once), at the same resolution and bias:
// a warp that loses to it by more than kLossRatio says so, and why, in a note.
std::optional<Note> warp_loss(const MeasureContext& c, const Method& warp, const Settings& settings, int resolution,
                              double bias, const Measurement& measured) {
    const Method& focused = *find_method("focused");
    const Measurement reference_map = measure_maps(c, focused, settings_like(focused, settings), resolution, bias);
    if (!(measured.error.misclassified > kLossRatio * reference_map.error.misclassified + kLossMargin))
        return std::nullopt;
    Trace trace;
    warp.compute_maps(inputs_for(c, warp, settings, resolution), settings, &trace);
    return Note{NoteKind::warp_loses, loss_cause(measured, reference_map, warp_choices(trace))};
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

Settings settings_like(const Method& other, const Settings& settings) {
    Settings out = resolve_settings(other.name, other.settings, {});
    for (const auto& [name, value] : settings.values())
        if (is_lookup_setting(name)) out.set(name, value);
    return out;
}

MeasureContext prepare_measurement(const Scene& scene, int width, int height, int light_samples) {
    MeasureContext c{scene, object_boxes(scene), tessellate(scene), caster_flags(scene), {}};
    const glm::ivec2 image = image_size_within(scene.camera, width, height);
    c.reference = light_reference(scene, c.triangles, image.x, image.y, light_samples);
    return c;
}

void add_storage_bounds(MeasureContext& context) {
    context.storage_bounds = storage_lower_bounds(context.scene, context.reference);
}

Measurement measure(const MeasureContext& c, const Method& method, const Settings& settings, int resolution,
                    double bias) {
    if (!method.makes_maps()) return measure_geometry(c, method, settings);
    Measurement m = measure_maps(c, method, settings, resolution, bias);
    if (is_perspective_warp(method.name))
        if (std::optional<Note> loss = warp_loss(c, method, settings, resolution, bias, m))
            m.fallbacks.push_back(std::move(*loss));
    return m;
}

}  // namespace shadowlab
