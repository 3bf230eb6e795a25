#include "metrics/pixel_cause.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "methods/step_figures.hpp"
#include "metrics/measurement.hpp"
#include "metrics/pixel_evidence.hpp"
#include "registry/method.hpp"

namespace shadowlab {
namespace {

bool has_setting(const Method& method, const std::string& name) {
    return std::any_of(method.settings.begin(), method.settings.end(),
                       [&](const SettingSpec& s) { return s.name == name; });
}

std::string number(double x) { return label_number(x); }

// The run with one setting changed.
Remedy changed(const RemedyInputs& in, const std::string& name, std::variant<double, std::string> value,
               const std::string& was) {
    Remedy r{.method = &in.method, .settings = in.settings, .resolution = in.resolution, .bias = in.bias};
    const std::string now =
        std::holds_alternative<double>(value) ? number(std::get<double>(value)) : std::get<std::string>(value);
    r.change = name + " " + was + " → " + now;
    r.settings.set(name, std::move(value));
    return r;
}

// Acne: the bias is shorter than the receiver's depth change across a texel: a slope-scaled bias
// in place of a constant --bias, else twice the slope scale (1 when it was 0).
std::optional<Remedy> more_slope_bias(const RemedyInputs& in) {
    const double slope = in.settings.number("bias_slope");
    if (in.bias >= 0.0) {
        Remedy r = changed(in, "bias_slope", std::max(slope, 1.0), number(slope));
        r.bias = -1.0;
        r.change = "bias " + number(in.bias) + " → slope-scaled ×" + number(std::max(slope, 1.0));
        return r;
    }
    return changed(in, "bias_slope", slope > 0.0 ? 2.0 * slope : 1.0, number(slope));
}

// Peter panning: the bias reaches past an occluder: a quarter of every bias.
std::optional<Remedy> less_bias(const RemedyInputs& in) {
    if (in.bias >= 0.0) {
        Remedy r{.method = &in.method, .settings = in.settings, .resolution = in.resolution, .bias = in.bias / 4};
        r.change = "bias " + number(in.bias) + " → " + number(r.bias);
        return r;
    }
    Remedy r{.method = &in.method, .settings = in.settings, .resolution = in.resolution, .bias = in.bias};
    for (const char* name : {"bias_constant", "bias_slope", "bias_normal"}) {
        const double was = in.settings.number(name);
        if (was <= 0.0) continue;
        r.settings.set(name, was / 4);
        r.change +=
            std::string(r.change.empty() ? "" : ", ").append(name) + " " + number(was) + " → " + number(was / 4);
    }
    return r.change.empty() ? std::nullopt : std::optional(r);
}

// Under-sampling and projection aliasing: the resolution at which the factor's 95th percentile
// comes to one texel per pixel (a power of two at least twice the run's, at most 8192), or the
// method's own finer texels where a setting sizes them (Method::finer_texels).
std::optional<Remedy> resolution_for(const RemedyInputs& in, double m_p95) {
    if (in.method.finer_texels) {  // its texels are a setting's, not the texture's
        std::optional<SettingsChange> finer = in.method.finer_texels(in.settings, m_p95);
        if (!finer) return std::nullopt;
        return Remedy{.change = std::move(finer->change),
                      .method = &in.method,
                      .settings = std::move(finer->settings),
                      .resolution = in.resolution,
                      .bias = in.bias};
    }
    int target = in.resolution * 2;
    while (target < 8192 && double(target) < in.resolution * m_p95) target *= 2;
    target = std::min(target, 8192);
    if (target <= in.resolution) return std::nullopt;
    Remedy r{.method = &in.method, .settings = in.settings, .resolution = target, .bias = in.bias};
    r.change = "resolution " + std::to_string(in.resolution) + " → " + std::to_string(target);
    return r;
}
std::optional<Remedy> finer_texels(const RemedyInputs& in) { return resolution_for(in, in.m_perspective_p95); }
std::optional<Remedy> finer_texels_for_projection(const RemedyInputs& in) { return resolution_for(in, in.m_p95); }

// Depth precision: a 32-bit float map, or reversed Z on one.
std::optional<Remedy> finer_depth(const RemedyInputs& in) {
    if (!has_setting(in.method, "depth_format")) return std::nullopt;
    const std::string format = in.settings.choice("depth_format");
    if (format != "float32") return changed(in, "depth_format", std::string("float32"), format);
    if (in.settings.choice("depth_reversed") == "off") return changed(in, "depth_reversed", std::string("on"), "off");
    return std::nullopt;
}

// Outside the map: a map that covers every visible receiver (the focused map, by its promise),
// read through the run's lookup settings.
std::optional<Remedy> covering_map(const RemedyInputs& in) {
    const Method* focused = find_method("focused");
    if (!focused || focused == &in.method) return std::nullopt;
    return Remedy{.change = "method " + in.method.name + " → focused (covers every visible receiver)",
                  .method = focused,
                  .settings = settings_like(*focused, in.settings),
                  .resolution = in.resolution,
                  .bias = in.bias};
}

// A seam: a blend band where there is none, twice as wide where there is one.
std::optional<Remedy> blend_band(const RemedyInputs& in) {
    if (!has_setting(in.method, "blend")) return std::nullopt;
    const double band = in.settings.number("blend");
    return changed(in, "blend", band > 0.0 ? std::min(2.0 * band, 0.5) : 0.2, number(band));
}

// A filter on the wrong side of ½ where the hard read is right: the hard read.
std::optional<Remedy> hard_read(const RemedyInputs& in) {
    return changed(in, "filter", std::string("hard"), in.settings.choice("filter"));
}

// Contact shadows darkening a point the map lights: a surface half as thick.
std::optional<Remedy> thinner_contact(const RemedyInputs& in) {
    const double thickness = in.settings.number("contact_thickness");
    return changed(in, "contact_thickness", thickness / 2, number(thickness));
}

bool within_one_step(const PixelEvidence& e) { return std::abs(e.gap) <= e.step; }

const std::vector<CauseInfo> kCauses{
    {PixelCause::technique,
     "technique",
     "a geometric technique's wrong pixel: no map was read (its limits say why)",
     {140, 140, 140},
     [](const PixelEvidence& e) { return e.technique; },
     nullptr},
    {PixelCause::contact,
     "contact",
     "false shadow the contact shadows add: the map lights the point, but the march toward the light passes behind "
     "a surface of the depth image taken to be contact_thickness deep (thin geometry, a ray passing behind an edge)",
     {170, 255, 195},
     [](const PixelEvidence& e) { return e.contact_darkened; },
     thinner_contact},
    {PixelCause::outside_map,
     "outside_map",
     "the point reads no map (off every tile, behind the near plane or past the far one), or no occluder at all "
     "reached the map where one should shadow it (a caster clipped by a near plane or a tile)",
     {230, 159, 0},
     [](const PixelEvidence& e) {
         return !e.reads_map || (!e.false_shadow && !e.straddles_edge && !e.unbiased_occluder && !within_one_step(e));
     },
     covering_map},
    {PixelCause::filter,
     "filter",
     "the filtered visibility lands on the wrong side of ½ where the hard read of the same texels is right "
     "(VSM's bleeding, a kernel wider than the penumbra)",
     {204, 121, 167},
     [](const PixelEvidence& e) { return e.filtered && e.hard_right; },
     hard_read},
    {PixelCause::seam,
     "seam",
     "inside a blend band whose two maps disagree, or where a map's coverage ends: beside the pixels of the next "
     "map (the next cascade), which reads the point right",
     {86, 180, 233},
     [](const PixelEvidence& e) { return e.seam; },
     blend_band},
    {PixelCause::depth_precision,
     "depth_precision",
     "the receiver and the stored depth differ by no more than one step of the map's depth format",
     {0, 158, 115},
     within_one_step,
     finer_depth},
    {PixelCause::acne,
     "acne",
     "false shadow from the receiver's own surface: the texel stores the receiver's plane and the bias is shorter "
     "than the plane's depth change across the texel",
     {213, 94, 0},
     [](const PixelEvidence& e) { return e.false_shadow && e.own_surface; },
     more_slope_bias},
    {PixelCause::peter_panning,
     "peter_panning",
     "false light where the unbiased read holds an occluder: the bias moved the point past it",
     {0, 114, 178},
     [](const PixelEvidence& e) { return !e.false_shadow && e.unbiased_occluder; },
     less_bias},
    {PixelCause::projection,
     "projection",
     "the texel's footprint straddles a shadow edge and the projection factor of m dominates (grazing light)",
     {240, 228, 66},
     [](const PixelEvidence& e) { return e.straddles_edge && e.projection_dominant; },
     finer_texels_for_projection},
    {PixelCause::under_sampling,
     "under_sampling",
     "the texel's footprint straddles a shadow edge and the perspective factor of m dominates",
     {200, 30, 30},
     [](const PixelEvidence& e) { return e.straddles_edge; },
     finer_texels},
    {PixelCause::undecided,
     "undecided",
     "no test above decides it (verdicts come from the light's centre ray, so a soft reference's noise leaves "
     "none undecided)",
     {255, 255, 255},
     [](const PixelEvidence&) { return true; },
     nullptr},
};

}  // namespace

const std::vector<CauseInfo>& all_causes() { return kCauses; }

const CauseInfo& info(PixelCause kind) {
    for (const CauseInfo& c : kCauses)
        if (c.kind == kind) return c;
    throw std::invalid_argument("no cause of that kind");
}

const char* to_string(PixelCause kind) { return kind == PixelCause::none ? "none" : info(kind).name; }

PixelCause cause_of(const PixelEvidence& evidence) {
    for (const CauseInfo& c : kCauses)
        if (c.holds(evidence)) return c.kind;
    return PixelCause::undecided;
}

}  // namespace shadowlab
