#include "measure_command.hpp"

#include <chrono>
#include <iostream>
#include <stdexcept>

#include "io/inspection_json.hpp"
#include "limits.hpp"
#include "metrics/measurement.hpp"
#include "scene/scene_loader.hpp"

namespace shadowlab {

Json to_json(const Measurement& m) {
    const ShadowError& e = m.error;
    Json out = {{"method", m.method},
            {"resolution", m.resolution},
            {"misclassified", e.misclassified},
            {"false_shadow", e.false_shadow},
            {"false_light", e.false_light},
            {"m", {{"max", e.m.max}, {"mean", e.m.mean}, {"p95", e.m.p95}}},
            {"depth_step", {{"max", e.depth_step.max}, {"mean", e.depth_step.mean}, {"p95", e.depth_step.p95}}},
            {"setup_ms", m.setup_ms},
            {"raster_ms", m.raster_ms},
            {"fallback", m.fallbacks.empty() ? Json(nullptr) : Json(describe(m.fallbacks))},
            {"fallbacks", to_json(m.fallbacks)},
            {"limits", to_json(m.limits)},
            {"bias", m.geometry ? Json(nullptr) : m.bias >= 0.0 ? Json(m.bias) : Json("slope-scaled")},
            {"receiver_pixels", e.receiver_pixels}};
    if (m.geometry) {
        out["polygons"] = m.geometry->polygons;
        out["fill_mean"] = m.geometry->fill_mean;
        out["fill_max"] = m.geometry->fill_max;
    }
    return out;
}

namespace {

void print_text(const MeasureOptions& o, const Measurement& m) {
    const ShadowError& e = m.error;
    std::cout << "method " << m.method;
    if (m.geometry)
        std::cout << " (geometry, no map), image " << o.width << "x" << o.height << "\n";
    else
        std::cout << " at " << m.resolution << "^2, image " << o.width << "x" << o.height << ", bias "
                  << (m.bias >= 0.0 ? std::to_string(m.bias) : std::string("slope-scaled")) << "\n";
    std::cout << "  misclassified " << 100 * e.misclassified << "% of " << e.receiver_pixels
              << " receiver pixels (false shadow " << 100 * e.false_shadow << "%, false light " << 100 * e.false_light
              << "%)\n";
    if (m.geometry)
        std::cout << "  polygons " << m.geometry->polygons << ", fill (fragments per pixel): mean "
                  << m.geometry->fill_mean << ", max " << m.geometry->fill_max << "\n";
    else
        std::cout << "  m (texel extent in pixels): max " << e.m.max << ", mean " << e.m.mean << ", p95 " << e.m.p95
                  << "\n  depth step of a 24-bit map (world units): max " << e.depth_step.max << ", mean "
                  << e.depth_step.mean << ", p95 " << e.depth_step.p95 << "\n";
    std::cout << "  cost: setup " << m.setup_ms << " ms, raster " << m.raster_ms << " ms, total "
              << m.setup_ms + m.raster_ms << " ms\n";
    if (m.geometry)
        std::cout << "  limits: " << (m.limits.empty() ? "none" : describe(m.limits)) << "\n";
    else
        std::cout << "  fallback: " << (m.fallbacks.empty() ? "none" : describe(m.fallbacks)) << "\n";
}

}  // namespace

std::vector<const Method*> methods_named(const std::vector<std::string>& names) {
    std::vector<const Method*> methods;
    for (const std::string& name : names) methods.push_back(&method_or_throw(name));
    if (!methods.empty()) return methods;
    for (const Method& m : all_methods()) methods.push_back(&m);
    return methods;
}

MeasureContext prepare_with_progress(const std::string& scene_file, int width, int height) {
    limits::check(limits::image_side, "--size width", width);
    limits::check(limits::image_side, "--size height", height);
    const Scene scene = load_scene(scene_file);
    std::cerr << "measure: exact reference of " << scene_file << " (" << width << "x" << height << ", Embree rays)..."
              << std::flush;
    const auto start = std::chrono::steady_clock::now();
    MeasureContext context = prepare_measurement(scene, width, height);
    std::cerr << " " << std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count()
              << " ms\n";
    return context;
}

void add_error_point(ChartSeries& series, double x, const Measurement& m) {
    series.x.push_back(x);
    series.y.push_back(100.0 * m.error.misclassified);
    series.marked.push_back(!m.notes().empty());
}

void run_measure(const MeasureOptions& o) {
    const Method& method = method_or_throw(o.method);
    limits::check(limits::map_resolution, "--resolution", o.resolution);
    const Settings settings = resolve_settings(method.name, method.settings, o.settings);
    const MeasureContext context = prepare_with_progress(o.scene_file, o.width, o.height);
    std::cerr << "measure: " << method.name;
    if (method.makes_maps()) std::cerr << " at " << o.resolution << "^2";
    std::cerr << "...\n";
    const Measurement m = measure(context, method, settings, o.resolution, o.bias);
    if (o.json)
        std::cout << to_json(m).dump(1) << "\n";
    else
        print_text(o, m);
}

}  // namespace shadowlab
