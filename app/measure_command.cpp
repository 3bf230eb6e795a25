#include "measure_command.hpp"

#include <chrono>
#include <iostream>
#include <stdexcept>

#include "io/inspection_json.hpp"
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
            {"fallback", m.fallback ? Json(*m.fallback) : Json(nullptr)},
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
              << m.setup_ms + m.raster_ms << " ms\n"
              << "  fallback: " << m.fallback.value_or("none") << "\n";
}

}  // namespace

NamedMethod method_named(const std::string& name) {
    if (const Method* m = find_method(name)) return {m, nullptr};
    if (const Technique* t = find_technique(name)) return {nullptr, t};
    std::string known;
    for (const Method& m : all_methods()) known += " " + m.name;
    for (const Technique& t : all_techniques()) known += " " + t.name;
    throw std::invalid_argument("unknown method '" + name + "' (known:" + known + ")");
}

std::vector<NamedMethod> methods_named(const std::vector<std::string>& names) {
    std::vector<NamedMethod> methods;
    for (const std::string& name : names) methods.push_back(method_named(name));
    if (!methods.empty()) return methods;
    for (const Method& m : all_methods()) methods.push_back({&m, nullptr});
    for (const Technique& t : all_techniques()) methods.push_back({nullptr, &t});
    return methods;
}

Measurement measure_named(const MeasureContext& context, const NamedMethod& method, const Settings& settings,
                          int resolution, double bias) {
    return method.map ? measure_method(context, *method.map, settings, resolution, bias)
                      : measure_technique(context, *method.technique, settings);
}

MeasureContext prepare_with_progress(const std::string& scene_file, int width, int height) {
    if (width < 1 || height < 1) throw std::invalid_argument("--size: expected positive WxH");
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
    series.marked.push_back(m.fallback.has_value());
}

void check_resolution(int resolution) {
    if (resolution < 1 || resolution > 16384)
        throw std::invalid_argument("--resolution: expected 1 to 16384, got " + std::to_string(resolution));
}

void run_measure(const MeasureOptions& o) {
    const NamedMethod method = method_named(o.method);
    check_resolution(o.resolution);
    const Settings settings = resolve_settings(method.name(), method.settings(), o.settings);
    const MeasureContext context = prepare_with_progress(o.scene_file, o.width, o.height);
    std::cerr << "measure: " << method.name();
    if (method.map) std::cerr << " at " << o.resolution << "^2";
    std::cerr << "...\n";
    const Measurement m = measure_named(context, method, settings, o.resolution, o.bias);
    if (o.json)
        std::cout << to_json(m).dump(1) << "\n";
    else
        print_text(o, m);
}

}  // namespace shadowlab
