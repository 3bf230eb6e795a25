#include "measure_command.hpp"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <variant>

#include "exchange/inspection_json.hpp"
#include "limits.hpp"
#include "scene/image_size.hpp"
#include "metrics/diagnosis.hpp"
#include "metrics/measurement.hpp"
#include "scene/scene_loader.hpp"

namespace shadowlab {

namespace {

Json to_json(const AliasingStats& s) { return {{"max", s.max}, {"mean", s.mean}, {"p95", s.p95}}; }

// Per map: the receiver pixels it serves, the share of them it misclassifies, its perspective m.
Json to_json(const MapBreakdown& b) {
    Json maps = Json::array();
    for (const MapShare& share : b.maps)
        maps.push_back({{"pixels", share.pixels},
                        {"misclassified", share.pixels ? double(share.misclassified) / share.pixels : 0.0},
                        {"m_perspective", to_json(share.m_perspective)}});
    return maps;
}

// Against the reference's visibility (soft for an area light): the error, the reference's own noise.
Json to_json(const VisibilityError& v) {
    return {{"rmse", v.rmse},
            {"mae", v.mae},
            {"mean_signed", v.mean_signed},
            {"reference_noise", v.reference_noise},
            {"penumbra_width_ratio", v.penumbra_width_ratio ? Json(*v.penumbra_width_ratio) : Json(nullptr)},
            {"light_bleeding", v.light_bleeding}};
}

// The filter and the bias the lookups applied: the filter's name, its texel reads and the settings
// it reads (its descriptor's), as given.
Json to_json(const ShadowLookup& l) {
    const ShadowFilter& f = l.filter;
    Json filter = {{"kind", f.kind}, {"taps", f.taps()}};
    for (const SettingSpec& spec : filter_of(f).settings)
        if (const auto value = f.settings.values().find(spec.name); value != f.settings.values().end())
            filter[spec.name] = std::visit([](const auto& v) { return Json(v); }, value->second);
    return {{"filter", filter},
            {"bias",
             {{"constant", l.bias.constant},
              {"slope_scale", l.bias.slope_scale},
              {"normal_offset_texels", l.bias.normal_offset},
              {"receiver_plane", l.bias.receiver_plane}}},
            {"contact",  // null: off
             l.contact.on()
                 ? Json{{"length", l.contact.length}, {"steps", l.contact.steps}, {"thickness", l.contact.thickness}}
                 : Json(nullptr)}};
}

// The texels its max perspective m asks, the view's lower bound, their ratio (metrics/storage_bound.hpp).
Json to_json(const StorageFactor& s) {
    return {{"needed", s.needed}, {"lower_bound", s.lower_bound}, {"efficiency", s.efficiency}};
}

}  // namespace

Json to_json(const Diagnosis& d) {
    Json causes = Json::array();
    for (const CauseCount& c : d.causes) {
        Json remedy = nullptr;
        if (c.remedy)
            remedy = {{"change", c.remedy->change},
                      {"removes", c.remedy->removes},
                      {"adds", c.remedy->adds},
                      {"misclassified", c.remedy->misclassified}};
        causes.push_back({{"kind", to_string(c.kind)}, {"pixels", c.pixels}, {"share", c.share}, {"remedy", remedy}});
    }
    return {{"misclassified_pixels", d.misclassified}, {"causes", causes}};
}

Json to_json(const Measurement& m) {
    const ShadowError& e = m.error;
    Json out = {{"method", m.method},
                {"resolution", m.resolution},
                {"texels_used", m.texels_used},
                {"misclassified", e.misclassified},
                {"false_shadow", e.false_shadow},
                {"false_light", e.false_light},
                {"m", to_json(e.m)},
                {"m_perspective", to_json(e.m_perspective)},
                {"m_projection", to_json(e.m_projection)},
                {"depth_step", to_json(e.depth_step)},
                {"depth_format", m.geometry ? Json(nullptr) : Json(describe(m.lookup.format))},
                {"setup_ms", m.setup_ms},
                {"raster_ms", m.raster_ms},
                {"fallback", m.fallbacks.empty() ? Json(nullptr) : Json(describe(m.fallbacks))},
                {"fallbacks", to_json(m.fallbacks)},
                {"limits", to_json(m.limits)},
                {"bias", m.geometry      ? Json(nullptr)
                         : m.bias >= 0.0 ? Json(m.bias)
                                         : Json(describe(m.lookup.bias))},
                {"receiver_pixels", e.receiver_pixels},
                {"visibility", to_json(e.visibility)},
                {"storage", m.storage ? to_json(*m.storage) : Json(nullptr)}};
    if (!m.geometry) {
        out["lookup"] = to_json(m.lookup);
        out["prefilter_ms"] = m.prefilter_ms;
        out["lookup_ms"] = m.lookup_ms;
        out["lookup_ns_per_pixel"] = e.receiver_pixels ? 1e6 * m.lookup_ms / double(e.receiver_pixels) : 0.0;
        out["taps_per_pixel"] = m.taps_per_pixel;
    }
    if (m.pages) out["pages"] = pages_json(*m.pages);
    if (m.by_map) {
        out["per_map"] = to_json(*m.by_map);
        out["seam_share"] = m.by_map->seam_share();  // of the misclassified pixels, near a boundary between maps
    }
    if (m.geometry) {
        out["polygons"] = m.geometry->polygons;
        out["fill_mean"] = m.geometry->fill_mean;
        out["fill_max"] = m.geometry->fill_max;
    }
    return out;
}

namespace {

std::ostream& operator<<(std::ostream& out, const AliasingStats& s) {
    return out << "max " << s.max << ", mean " << s.mean << ", p95 " << s.p95;
}

// `image`: the camera image measured (the camera's aspect within --size).
void print_text(const Measurement& m, const glm::ivec2& image) {
    const ShadowError& e = m.error;
    std::cout << "method " << m.method;
    if (m.geometry)
        std::cout << " (geometry, no map), image " << image.x << "x" << image.y << "\n";
    else
        std::cout << " at " << m.resolution << "^2, image " << image.x << "x" << image.y << ", bias "
                  << (m.bias >= 0.0 ? std::to_string(m.bias) + " (--bias)" : describe(m.lookup.bias)) << "\n";
    std::cout << "  misclassified " << 100 * e.misclassified << "% of " << e.receiver_pixels
              << " receiver pixels (false shadow " << 100 * e.false_shadow << "%, false light " << 100 * e.false_light
              << "%)\n";
    if (m.geometry)
        std::cout << "  polygons " << m.geometry->polygons << ", fill (fragments per pixel): mean "
                  << m.geometry->fill_mean << ", max " << m.geometry->fill_max << "\n";
    else
        std::cout << "  m (texel extent in pixels): " << e.m
                  << "\n    perspective factor (the parameterization's part): " << e.m_perspective
                  << "\n    projection factor (the surface's tilt): " << e.m_projection << "\n  depth step of the "
                  << describe(m.lookup.format) << " map (world units): " << e.depth_step << "\n";
    if (m.pages) {
        const PageCounts& n = m.pages->counts;
        std::cout << "  pages: " << m.pages->pages.size() << " resident of " << n.marked << " marked, budget "
                  << n.budget << " of " << m.pages->page_size << "^2 texels, " << n.over_budget
                  << " fell to a coarser level, " << n.dropped << " without a slot\n";
    }
    if (m.by_map && !m.pages) {  // per page would be hundreds of lines: the JSON has them
        for (size_t k = 0; k < m.by_map->maps.size(); ++k) {
            const MapShare& share = m.by_map->maps[k];
            std::cout << "  map " << k << ": " << share.pixels << " receiver pixels, misclassified "
                      << (share.pixels ? 100.0 * share.misclassified / share.pixels : 0.0) << "%, m perspective "
                      << share.m_perspective << "\n";
        }
        std::cout << "  seams: " << 100 * m.by_map->seam_share() << "% of the misclassified pixels lie within "
                  << kSeamPixels << " pixels of a boundary between maps\n";
    }
    const VisibilityError& v = e.visibility;
    std::cout << "  visibility against the " << (v.reference_noise > 0.0 ? "soft" : "hard") << " reference: RMSE "
              << v.rmse << ", MAE " << v.mae << " (reference noise " << v.reference_noise << "), light bleeding "
              << 100 * v.light_bleeding << "%";
    if (v.penumbra_width_ratio) std::cout << ", penumbra width x" << *v.penumbra_width_ratio;
    std::cout << "\n";
    if (!m.geometry)
        std::cout << "  lookup: filter " << m.lookup.filter.kind << ", " << m.taps_per_pixel << " taps per pixel, "
                  << m.lookup_ms << " ms for " << e.receiver_pixels << " pixels"
                  << (m.prefilter_ms > 0.0 ? ", moments blurred in " + std::to_string(m.prefilter_ms) + " ms" : "")
                  << (m.lookup.contact.on() ? "; " + describe(m.lookup.contact) : "") << "\n";
    if (m.texels_used > 0.0)
        std::cout << "  texels: " << m.texels_used << " in the maps' tiles, of " << double(m.resolution) * m.resolution
                  << " in the texture\n";
    if (m.storage)
        std::cout << "  storage: " << m.storage->needed << " texels for max perspective m 1, the view's lower bound "
                  << m.storage->lower_bound << ": efficiency " << m.storage->efficiency << "\n";
    std::cout << "  cost: setup " << m.setup_ms << " ms, raster " << m.raster_ms << " ms, total "
              << m.setup_ms + m.raster_ms << " ms\n";
    if (m.geometry)
        std::cout << "  limits: " << (m.limits.empty() ? "none" : describe(m.limits)) << "\n";
    else
        std::cout << "  fallback: " << (m.fallbacks.empty() ? "none" : describe(m.fallbacks)) << "\n";
}

// The ranked causes, each with its remedy's outcome.
void print_text(const Diagnosis& d) {
    if (d.causes.empty()) return;
    std::cout << "  why (" << d.misclassified << " misclassified pixels, by cause):\n";
    char line[256];
    std::snprintf(line, sizeof line, "    %-16s %8s %8s  %s\n", "cause", "pixels", "share", "remedy: removes, adds");
    std::cout << line;
    for (const CauseCount& c : d.causes) {
        std::snprintf(line, sizeof line, "    %-16s %8zu %7.3f%%  ", to_string(c.kind), c.pixels, 100.0 * c.share);
        std::cout << line;
        if (c.remedy)
            std::cout << c.remedy->change << ": removes " << 100.0 * c.remedy->removes << "% of it, adds "
                      << 100.0 * c.remedy->adds << "% elsewhere (misclassified " << 100.0 * c.remedy->misclassified
                      << "% after)\n";
        else
            std::cout << "none to measure\n";
    }
}

}  // namespace

std::vector<const Method*> methods_named(const std::vector<std::string>& names) {
    std::vector<const Method*> methods;
    for (const std::string& name : names) methods.push_back(&method_or_throw(name));
    if (!methods.empty()) return methods;
    for (const Method& m : all_methods()) methods.push_back(&m);
    return methods;
}

MeasureContext prepare_with_progress(const std::string& scene_file, const SceneSource& source, int width, int height) {
    // A bad size stops before the scene is read.
    limits::check(limits::image_side, "--size width", width);
    limits::check(limits::image_side, "--size height", height);
    return prepare_with_progress(load_scene_source(scene_file, source), scene_file, width, height);
}

MeasureContext prepare_with_progress(const Scene& scene, const std::string& label, int width, int height) {
    limits::check(limits::image_side, "--size width", width);
    limits::check(limits::image_side, "--size height", height);
    const glm::ivec2 image = image_size_within(scene.camera, width, height);
    std::cerr << "measure: exact reference of " << label << " (" << image.x << "x" << image.y;
    if (image != glm::ivec2(width, height))
        std::cerr << ": the camera's aspect " << scene.camera.aspect << " within " << width << "x" << height;
    std::cerr << ", Embree rays)..." << std::flush;
    const auto start = std::chrono::steady_clock::now();
    MeasureContext context = prepare_measurement(scene, width, height);
    std::cerr << " " << std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count()
              << " ms\n";
    std::cerr << "measure: the view's storage bound..." << std::flush;
    const auto bound_start = std::chrono::steady_clock::now();
    add_storage_bounds(context);
    std::cerr << " "
              << std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - bound_start).count()
              << " ms\n";
    return context;
}

void add_error_point(ChartSeries& series, double x, const Measurement& m) {
    series.x.push_back(x);
    series.y.push_back(100.0 * m.error.misclassified);
    series.marked.push_back(!m.notes().empty());
}

MeasureRun measure_on(const MeasureContext& context, const MeasureOptions& o, bool diagnose) {
    const Method& method = method_or_throw(o.method);
    if (method.makes_maps())
        limits::check(limits::map_resolution, "--resolution", o.resolution);  // a technique has none
    const Settings settings = resolve_settings(method.name, method.settings, o.settings);
    std::cerr << "measure: " << method.name;
    if (method.makes_maps()) std::cerr << " at " << o.resolution << "^2";
    std::cerr << "...\n";
    MeasureRun run{.measurement = measure(context, method, settings, o.resolution, o.bias)};
    if (diagnose)
        run.diagnosis = shadowlab::diagnose(context, method, settings, o.resolution, o.bias, run.measurement,
                                            [](const CauseInfo& cause, const Remedy& remedy) {
                                                std::cerr << "measure: remedy for " << cause.name << ": "
                                                          << remedy.change << "...\n";
                                            });
    return run;
}

Json to_json(const MeasureRun& run, const MeasureContext& context) {
    Json json = to_json(run.measurement);
    if (run.diagnosis) json["diagnosis"] = to_json(*run.diagnosis);
    json["image"] = {context.reference.width, context.reference.height};  // the size the camera's aspect left
    return json;
}

void run_measure(const MeasureOptions& o) {
    const Method& method = method_or_throw(o.method);
    if (method.makes_maps())
        limits::check(limits::map_resolution, "--resolution", o.resolution);  // a technique has none
    resolve_settings(method.name, method.settings, o.settings);  // a bad setting stops before the reference
    const MeasureContext context = prepare_with_progress(o.scene_file, o.scene_source, o.width, o.height);
    const MeasureRun run = measure_on(context, o);
    if (o.json) {
        std::cout << to_json(run, context).dump(1) << "\n";
    } else {
        print_text(run.measurement, {context.reference.width, context.reference.height});
        print_text(*run.diagnosis);
    }
}

}  // namespace shadowlab
