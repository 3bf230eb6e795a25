#include "what_goes_wrong.hpp"

#include <cstdio>

#include "views/offscreen_view.hpp"

namespace shadowlab {
namespace {

std::string percent(double share, int decimals) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*f %%", decimals, 100.0 * share);
    return text;
}

std::string cause_row(const CauseCount& c) {
    const CauseInfo& cause = info(c.kind);
    char swatch[96];
    std::snprintf(swatch, sizeof swatch, "<span class=\"swatch\" style=\"background: rgb(%d, %d, %d)\"></span>",
                  cause.colour[0], cause.colour[1], cause.colour[2]);
    std::string row = "<tr><td>" + std::string(swatch) + "<code>" + cause.name + "</code></td><td class=\"number\">" +
                      std::to_string(c.pixels) + "</td><td class=\"number\">" + percent(c.share, 3) + "</td><td>" +
                      html_escaped(cause.meaning) + "</td>";
    if (!c.remedy) return row + "<td colspan=\"3\">none to measure</td></tr>";
    return row + "<td>" + html_escaped(c.remedy->change) + "</td><td class=\"number\">" +
           percent(c.remedy->removes, 1) + " of it</td><td class=\"number\">" + percent(c.remedy->adds, 3) +
           " elsewhere (" + percent(c.remedy->misclassified, 3) + " misclassified after)</td></tr>";
}

}  // namespace

std::string what_goes_wrong_section(const Inspection& in, const MeasureContext& context, const Measurement& run,
                                    const Diagnosis& d, const WrongSection& section, const PictureSource& source) {
    std::string html =
        "<section id=\"" + html_escaped(section.id) + "\"><h2>" + html_escaped(section.heading) + "</h2>\n<p>";
    const std::string judged = std::to_string(context.reference.width) + "x" + std::to_string(context.reference.height);
    if (d.causes.empty()) {
        html += "Against the exact reference of the " + judged + " camera image, no receiver pixel is misclassified.";
    } else {
        html += std::to_string(d.misclassified) + " of " + std::to_string(run.error.receiver_pixels) +
                " receiver pixels of the " + judged + " camera image are misclassified against the exact reference (" +
                percent(run.error.misclassified, 3) +
                "). Each has the cause its lookup read; each cause's remedy was measured on the same reference.";
    }
    html += "</p>\n";
    if (!d.causes.empty()) {
        html +=
            "<table class=\"causes\"><tr><th>cause</th><th>pixels</th><th>share</th><th>meaning</th>"
            "<th>remedy</th><th>removes</th><th>adds</th></tr>\n";
        for (const CauseCount& c : d.causes) html += cause_row(c) + "\n";
        html += "</table>\n";
    }
    const ViewOptions options{
        .width = context.reference.width, .height = context.reference.height, .error = ErrorShown::causes};
    const RgbImage causes = render_view(in, view_or_throw("error"), options, section.width, section.height);
    return html +
           picture_figure(source(causes, section.picture), section.width,
                          "Error, each misclassified pixel in its cause's colour") +
           "</section>\n";
}

std::string what_goes_wrong(const Inspection& in, const LessonOptions& o, const PictureSource& source) {
    const MeasureContext context = prepare_measurement(in.scene, o.width, o.height);
    const Measurement run = measure(context, *in.method, in.settings, in.resolution, in.bias);
    const Diagnosis d = diagnose(context, *in.method, in.settings, in.resolution, in.bias, run);
    return what_goes_wrong_section(in, context, run, d, {.width = o.width, .height = o.height}, source);
}

}  // namespace shadowlab
