// The Error view: the camera image measured against the exact reference, in one of two ways
// (ErrorShown). The verdicts: misclassified pixels are painted by kind (error_colours.hpp: false
// shadow blue, false light green, each grown to a 3x3 block so that a lone pixel is seen) and named
// in a legend. For a map the other receiver pixels show Lloyd's m, or the factor of it the options
// choose, as a heat map (log scale, 1/8 to 8, its colour bar at the top left), judged through the
// inspection's lookup (its filter and bias); a geometric technique has no texels, so its agreeing
// pixels are light grey where lit and dark grey where shadowed. The signed visibility error, where
// shadows are soft (a verdict of a penumbra pixel says little): each judged pixel's method −
// reference visibility on a diverging ramp, blue too dark, white exact, red too light, with the RMSE,
// MAE and the reference's own noise. Where no surface is judged, the greys of the verdicts. The
// causes: each misclassified pixel in its cause's colour (the table of metrics/pixel_cause.hpp), a
// legend ranking the causes present by their pixels; the agreeing pixels in the technique's greys
// for every method (the heat map's reds, oranges and yellows would pass for causes' colours).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include <vtkRenderer.h>

#include "metrics/diagnosis.hpp"
#include "metrics/shadow_error.hpp"
#include "reference/exact_shadows.hpp"
#include "views/colour_bar.hpp"
#include "views/error_colours.hpp"
#include "views/space_parts.hpp"
#include "views/view_parts.hpp"

namespace shadowlab {
namespace {

namespace colours = error_colours;

// The heat map's range: m from 2^-kLog2Range to 2^kLog2Range, on a log scale.
constexpr double kLog2Range = 3.0;
double heat_position(double m) { return (std::log2(std::max(m, 1e-3)) + kLog2Range) / (2.0 * kLog2Range); }

// The per-pixel quantity the heat map shows, its statistics, and its name in the caption (as in
// `measure --json`).
struct Shown {
    const std::vector<float>& image;
    const AliasingStats& stats;
    const char* name;
};

Shown shown(const ShadowError& e, AliasingShown which) {
    switch (which) {
        case AliasingShown::perspective: return {e.m_perspective_image, e.m_perspective, "m_perspective"};
        case AliasingShown::projection: return {e.m_projection_image, e.m_projection, "m_projection"};
        case AliasingShown::total: break;
    }
    return {e.m_image, e.m, "m"};
}

Rgb unjudged_colour(const ReferenceImage& ref, size_t i) {
    return ref.visible[i] ? colours::kNotJudged : colours::kNotVisible;
}

// An agreeing pixel: m on the heat map, if given, else grey by the reference's verdict.
Rgb pixel_colour(const ShadowError& e, const ReferenceImage& ref, const std::vector<float>* heat_image, size_t i) {
    if (e.verdicts[i] == PixelVerdict::agree) {
        if (heat_image) return heat(heat_position((*heat_image)[i]));
        return ref.lit[i] ? colours::kAgreeLit : colours::kAgreeShadowed;
    }
    return unjudged_colour(ref, i);
}

RgbImage paint_agreeing(const ShadowError& e, const ReferenceImage& ref, const std::vector<float>* heat_image) {
    RgbImage image(ref.width, ref.height);
    for (size_t i = 0; i < ref.visible.size(); ++i) {
        const Rgb c = pixel_colour(e, ref, heat_image, i);
        std::copy(c.begin(), c.end(), image.rgb.begin() + 3 * i);
    }
    return image;
}

// Each misclassified pixel as a 3x3 block of its kind's colour; false light drawn last, on top.
void mark_misclassified(RgbImage& image, const ShadowError& e) {
    for (const auto& [kind, colour] : {std::pair{PixelVerdict::false_shadow, colours::kFalseShadow},
                                       std::pair{PixelVerdict::false_light, colours::kFalseLight}})
        for (size_t i = 0; i < e.verdicts.size(); ++i)
            if (e.verdicts[i] == kind) fill_block(image, i, colour);
}

// Each misclassified pixel as a 3x3 block of its cause's colour, the rarer causes' blocks drawn over
// the commoner's; then every misclassified pixel itself in its own cause's colour, so that a block
// never hides another cause's pixel.
void mark_causes(RgbImage& image, const ShadowError& e, const Diagnosis& d) {
    for (const CauseCount& cause : d.causes)
        for (size_t i = 0; i < e.causes.size(); ++i)
            if (e.causes[i] == cause.kind) fill_block(image, i, info(cause.kind).colour);
    for (size_t i = 0; i < e.causes.size(); ++i)
        if (e.causes[i] != PixelCause::none) {
            const Rgb& colour = info(e.causes[i]).colour;
            std::copy(colour.begin(), colour.end(), image.rgb.begin() + 3 * i);
        }
}

RgbImage paint_signed_error(const VisibilityError& v, const ReferenceImage& ref) {
    RgbImage image(ref.width, ref.height);
    for (size_t i = 0; i < ref.visible.size(); ++i) {
        const Rgb c = v.image[i] >= 0.0f ? colours::signed_error_colour(v.signed_error[i]) : unjudged_colour(ref, i);
        std::copy(c.begin(), c.end(), image.rgb.begin() + 3 * i);
    }
    return image;
}

glm::dvec3 unit_colour(const error_colours::Colour& c) { return glm::dvec3(c[0], c[1], c[2]) / 255.0; }

void add_misclassified_legend(vtkRenderer* renderer) {
    add_legend(renderer, {{unit_colour(colours::kFalseShadow), "false shadow (acne)"},
                          {unit_colour(colours::kFalseLight), "false light (leak)"}});
}

// The causes present, most pixels first: "acne 1234 px (0.512%)".
void add_causes_legend(vtkRenderer* renderer, const Diagnosis& d) {
    std::vector<LegendEntry> entries;
    for (const CauseCount& c : d.causes) {
        char text[120];
        std::snprintf(text, sizeof text, "%s %zu px (%.3f%%)", to_string(c.kind), c.pixels, 100 * c.share);
        entries.push_back({unit_colour(info(c.kind).colour), text});
    }
    add_legend(renderer, entries);
}

void add_aliasing_bar(vtkRenderer* renderer, const char* quantity) {
    const std::string q = quantity;
    add_colour_bar(renderer, {.ramp = heat,
                              .ticks = {"1/8", "1/4", "1/2", "1", "2", "4", "8"},
                              .low_side = "over-sampled (" + q + " < 1):\ntexel smaller than pixel",
                              .high_side = "under-sampled (" + q + " > 1):\ntexel larger than pixel"});
}

void add_signed_error_bar(vtkRenderer* renderer) {
    add_colour_bar(renderer, {.ramp = [](double t) { return colours::signed_error_colour(2.0 * t - 1.0); },
                              .ticks = {"−1", "−0.5", "0", "+0.5", "+1"},
                              .low_side = "too dark (< 0):\nmethod darker",
                              .high_side = "too light (> 0):\nmethod lighter",
                              .title = "visibility error: method − reference"});
}

// What the method is judged against, and with which lookup: "focused 2048², filter pcf, against the
// soft reference (64 rays per pixel)".
std::string judged_as(const Inspection& in, const ReferenceImage& ref) {
    char text[200];
    if (in.has_map())
        std::snprintf(text, sizeof text, "%s %d², filter %s", in.name().c_str(), in.resolution,
                      in.lookup.filter.kind.c_str());
    else
        std::snprintf(text, sizeof text, "%s", in.name().c_str());
    if (ref.light_samples == 0) return text + std::string(", against the exact reference");
    return text + (", against the soft reference (" + std::to_string(ref.light_samples) + " rays per pixel)");
}

// Why the automatic choice paints the signed error (soft_shadows).
std::string why_signed(const Inspection& in) {
    if (in.scene.light.is_area()) return "the light has a size";
    return "filter " + in.lookup.filter.kind + " is not hard";
}

std::string visibility_summary(const VisibilityError& v) {
    char text[200];
    std::snprintf(text, sizeof text, "RMSE %.3f, MAE %.3f (reference noise %.3f)", v.rmse, v.mae, v.reference_noise);
    std::string out = text;
    if (v.penumbra_width_ratio) {
        std::snprintf(text, sizeof text, "; penumbra width ×%.2f", *v.penumbra_width_ratio);
        out += text;
    }
    std::snprintf(text, sizeof text, "; light bleeding %.1f%%", 100 * v.light_bleeding);
    return out + text;
}

std::string shares(const ShadowError& e) {
    char text[160];
    std::snprintf(text, sizeof text, "%.3f%% misclassified (false shadow %.3f%%, false light %.3f%%)",
                  100 * e.misclassified, 100 * e.false_shadow, 100 * e.false_light);
    return text;
}

}  // namespace

// A technique is judged on the image it ran on; a map on an image of the panel's size.
glm::ivec2 judged_image_size(const Inspection& in, const ViewOptions& options) {
    if (!in.has_map()) return {in.image_width, in.image_height};
    const int width = options.width > 0 ? options.width : 640;
    return {width, options.height > 0 ? options.height
                                      : std::max(1, static_cast<int>(std::lround(width / in.scene.camera.aspect)))};
}

namespace {

ViewReport build_error_view(vtkRenderer* renderer, const Inspection& in, const ViewOptions& options) {
    const glm::dvec3 background = unit_colour(colours::kNotVisible);
    renderer->SetBackground(background.r, background.g, background.b);
    const glm::ivec2 judged = judged_image_size(in, options);
    const ReferenceImage& ref = in.reference(judged.x, judged.y);
    const ShadowError& e = in.error(judged.x, judged.y);
    if (shows_signed_error(in, options.error)) {
        show_image(renderer, paint_signed_error(e.visibility, ref));
        add_signed_error_bar(renderer);
        const std::string why = options.error == ErrorShown::automatic ? " (signed: " + why_signed(in) + ")" : "";
        add_caption(renderer, "Error — " + judged_as(in, ref) + why + ": " + visibility_summary(e.visibility));
        return {};
    }
    if (options.error == ErrorShown::causes) {
        const Diagnosis d = count_causes(e);
        RgbImage image = paint_agreeing(e, ref, nullptr);
        mark_causes(image, e, d);
        show_image(renderer, image);
        add_causes_legend(renderer, d);
        const std::string what = in.has_map() ? " " + std::to_string(in.resolution) + "²" : "";
        add_caption(renderer, "Error — " + in.name() + what + ": " + shares(e) +
                                  "; coloured by cause, agreeing pixels grey (light: lit)");
        return {};
    }
    const Shown aliasing = shown(e, options.aliasing);
    RgbImage image = paint_agreeing(e, ref, in.has_map() ? &aliasing.image : nullptr);
    mark_misclassified(image, e);
    show_image(renderer, image);
    add_misclassified_legend(renderer);
    if (!in.has_map()) {
        add_caption(renderer, "Error — " + in.name() + ": " + shares(e) + "; agreeing pixels grey (light: lit)");
        return {};
    }
    add_aliasing_bar(renderer, aliasing.name);
    char caption[160];
    std::snprintf(caption, sizeof caption, "; %s max %.2f, p95 %.2f", aliasing.name, aliasing.stats.max,
                  aliasing.stats.p95);
    add_caption(renderer, "Error — " + in.name() + " " + std::to_string(in.resolution) + "²: " + shares(e) + caption);
    return {};
}

}  // namespace

View error_view() {
    return {.name = "error",
            .title = "Error",
            .prepare =
                [](const Inspection& in, const ViewOptions& options) {
                    const glm::ivec2 size = judged_image_size(in, options);
                    in.error(size.x, size.y);
                },
            .build = build_error_view,
            .choosers = {.error = true, .aliasing = true},
            .interaction = {.drag = ViewDrag::pans_image}};
}

}  // namespace shadowlab
