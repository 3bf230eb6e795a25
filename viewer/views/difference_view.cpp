// The Difference view: two configurations (A, the inspection drawn, and B, ViewOptions::compared)
// judged against the same exact reference, each receiver pixel coloured by who is right there
// (metrics/verdict_comparison.hpp): both, neither, only A or only B. The pixels where the verdicts
// differ are grown to 3x3 blocks over the agreeing ones, so that a lone one is seen (each such pixel
// itself keeps its own colour); a legend counts each class. Without a
// B (the window outside compare mode, `render --view difference`) it says how to give it one.
#include <cstdio>
#include <tuple>

#include <vtkRenderer.h>

#include "metrics/verdict_comparison.hpp"
#include "views/difference_colours.hpp"
#include "views/error_colours.hpp"
#include "views/space_parts.hpp"
#include "views/view_parts.hpp"

namespace shadowlab {
namespace {

namespace colours = difference_colours;

glm::dvec3 unit_colour(const colours::Colour& c) { return glm::dvec3(c[0], c[1], c[2]) / 255.0; }

// One camera image for both: a technique's own (it was judged on it), else the panel's.
glm::ivec2 compared_image_size(const Inspection& a, const Inspection& b, const ViewOptions& options) {
    return judged_image_size(a.has_map() ? b : a, options);
}

std::string setting_text(const std::variant<double, std::string>& value) {
    if (const auto* text = std::get_if<std::string>(&value)) return *text;
    char number[32];
    std::snprintf(number, sizeof number, "%g", std::get<double>(value));
    return number;
}

// "lispsm 1024² filter=pcf": the method, its map's resolution, and the settings in which it differs
// from the other configuration of the same method.
// (Appended piece by piece: GCC 12's false -Wrestrict on a literal + std::string, ARCHITECTURE.md.)
std::string configuration(const Inspection& in, const Inspection& other) {
    std::string text = in.name();
    if (in.has_map()) text.append(" ").append(std::to_string(in.resolution)).append("²");
    if (in.method != other.method) return text;
    for (const auto& [name, value] : in.settings.values())
        if (const auto theirs = other.settings.values().find(name);
            theirs == other.settings.values().end() || theirs->second != value)
            text.append(" ").append(name).append("=").append(setting_text(value));
    if (in.bias != other.bias) text.append(" bias ").append(in.bias < 0.0 ? "slope-scaled" : setting_text(in.bias));
    return text;
}

RgbImage paint_agreement(const VerdictComparison& c, const ReferenceImage& ref) {
    RgbImage image(ref.width, ref.height);
    for (size_t i = 0; i < c.pixels.size(); ++i) {
        const colours::Colour colour = c.pixels[i] == PixelAgreement::both_right ? colours::kBothRight
                                       : c.pixels[i] == PixelAgreement::both_wrong
                                           ? colours::kBothWrong
                                           : (ref.visible[i] ? error_colours::kNotJudged : error_colours::kNotVisible);
        std::copy(colour.begin(), colour.end(), image.rgb.begin() + 3 * i);
    }
    const auto differing = [](PixelAgreement p) -> const colours::Colour* {
        return p == PixelAgreement::only_a_right   ? &colours::kOnlyARight
               : p == PixelAgreement::only_b_right ? &colours::kOnlyBRight
                                                   : nullptr;
    };
    for (size_t i = 0; i < c.pixels.size(); ++i)
        if (const colours::Colour* colour = differing(c.pixels[i])) fill_block(image, i, *colour);
    for (size_t i = 0; i < c.pixels.size(); ++i)  // each pixel itself last: no block hides the other's
        if (const colours::Colour* colour = differing(c.pixels[i]))
            std::copy(colour->begin(), colour->end(), image.rgb.begin() + 3 * i);
    return image;
}

std::string pixels_and_share(size_t pixels, size_t of) {
    char text[64];
    std::snprintf(text, sizeof text, "%zu px (%.3f%%)", pixels, of ? 100.0 * double(pixels) / double(of) : 0.0);
    return text;
}

void add_agreement_legend(vtkRenderer* renderer, const VerdictComparison& c) {
    std::vector<LegendEntry> entries;
    for (const auto& [colour, name, pixels] : {std::tuple{colours::kOnlyARight, "only A right ", c.only_a_right},
                                               std::tuple{colours::kOnlyBRight, "only B right ", c.only_b_right},
                                               std::tuple{colours::kBothWrong, "both wrong ", c.both_wrong},
                                               std::tuple{colours::kBothRight, "both right ", c.both_right}})
        entries.push_back({unit_colour(colour), std::string(name).append(pixels_and_share(pixels, c.receiver_pixels))});
    const error_colours::Colour& unjudged = error_colours::kNotJudged;
    entries.push_back({glm::dvec3(unjudged[0], unjudged[1], unjudged[2]) / 255.0, "not judged (receives no shadow)"});
    add_legend(renderer, entries);
}

ViewReport build_difference_view(vtkRenderer* renderer, const Inspection& a, const ViewOptions& options) {
    const glm::dvec3 background = unit_colour(error_colours::kNotVisible);
    renderer->SetBackground(background.r, background.g, background.b);
    if (!options.compared) {
        const std::string note =
            "the Difference view compares two configurations: View > Compare in the window, `shadowlab compare` "
            "on the command line";
        add_caption(renderer, std::string("Difference — ").append(note));
        return {.notes = {note}};
    }
    const Inspection& b = *options.compared;
    const glm::ivec2 size = compared_image_size(a, b, options);
    const VerdictComparison c = compare_verdicts(a.error(size.x, size.y), b.error(size.x, size.y));
    show_image(renderer, paint_agreement(c, a.reference(size.x, size.y)));
    add_agreement_legend(renderer, c);
    add_caption(renderer, std::string("Difference — A: ")
                              .append(configuration(a, b))
                              .append(", B: ")
                              .append(configuration(b, a))
                              .append(": verdicts differ at ")
                              .append(pixels_and_share(c.differing(), c.receiver_pixels))
                              .append(" of the receiver pixels, against the exact reference"));
    return {};
}

}  // namespace

View difference_view() {
    return {.name = "difference",
            .title = "Difference",
            .prepare =
                [](const Inspection& a, const ViewOptions& options) {
                    if (!options.compared) return;
                    const glm::ivec2 size = compared_image_size(a, *options.compared, options);
                    a.error(size.x, size.y);
                    options.compared->error(size.x, size.y);
                },
            .build = build_difference_view,
            .choosers = {},
            .interaction = {.drag = ViewDrag::pans_image}};
}

}  // namespace shadowlab
