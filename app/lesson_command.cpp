#include "lesson_command.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "interactive_lesson.hpp"
#include "lesson_page.hpp"
#include "limits.hpp"
#include "metrics/diagnosis.hpp"
#include "views/offscreen_view.hpp"

namespace shadowlab {
namespace {

std::string picture_file(size_t step, const Picture& p) {
    char name[96];
    std::snprintf(name, sizeof name, "step-%02zu-%s-%s.png", step + 1, p.view->name.c_str(), to_string(p.preset));
    return name;
}

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

// "What goes wrong": the run measured against the exact reference of the pictures' camera image,
// its misclassified pixels ranked by cause (metrics/pixel_cause.hpp) with each cause's remedy
// measured (metrics/diagnosis.hpp: what share of the cause it removes, what it adds elsewhere), and
// the Error view coloured by cause over the same pixels.
std::string what_goes_wrong(const Inspection& in, const LessonOptions& o, const std::filesystem::path& dir) {
    const MeasureContext context = prepare_measurement(in.scene, o.width, o.height);
    const Measurement run = measure(context, *in.method, in.settings, in.resolution, in.bias);
    const Diagnosis d = diagnose(context, *in.method, in.settings, in.resolution, in.bias, run);
    std::string html = "<section id=\"what-goes-wrong\"><h2>What goes wrong</h2>\n<p>";
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
    const char* file = "what-goes-wrong-error-causes.png";
    const ViewOptions options{
        .width = context.reference.width, .height = context.reference.height, .error = ErrorShown::causes};
    write_png(render_view(in, view_or_throw("error"), options, o.width, o.height), (dir / file).string());
    return html + "<figure><img src=\"" + file + "\" width=\"" + std::to_string(o.width) +
           "\" alt=\"Error by cause\"><figcaption>Error, each misclassified pixel in its cause's colour</figcaption>"
           "</figure></section>\n";
}

}  // namespace

int run_lesson(const LessonOptions& o) {
    limits::check(limits::image_side, "--size width", o.width);
    limits::check(limits::image_side, "--size height", o.height);
    if (o.out.empty()) throw std::invalid_argument("--out: a directory is required");
    const Inspection in = inspect_for_lesson(o);
    const std::filesystem::path dir(o.out);
    std::filesystem::create_directories(dir);
    const MatrixLayout layout = o.row_vectors ? MatrixLayout::row_vectors : MatrixLayout::column_vectors;
    if (o.interactive) return write_interactive_lesson(in, o, layout, dir / "index.html");
    std::string html = page_head(in, o, layout);
    const std::vector<Step>& steps = in.trace.steps();
    int pictures = 0;
    for (size_t i = 0; i < steps.size(); ++i) {
        const Step& step = steps[i];
        html +=
            "<section id=\"" + html_escaped(step.id) + "\">" + step_heading(step, i, steps.size(), layout) + "<div>";
        for (const Picture& p : pictures_of(in, i)) {
            const std::string file = picture_file(i, p);
            const glm::ivec2 size = picture_size(in, p, o);
            write_png(render_view(in, *p.view, {.step = step.id, .preset = p.preset}, size.x, size.y),
                      (dir / file).string());
            ++pictures;
            html += "<figure><img src=\"" + file + "\" width=\"" + std::to_string(size.x) + "\" alt=\"" +
                    html_escaped(p.title) + "\"><figcaption>" + html_escaped(p.title) + "</figcaption></figure>";
        }
        html += "</div></section>\n";
    }
    html += what_goes_wrong(in, o, dir);
    ++pictures;
    html += "</body></html>\n";
    write_page(dir / "index.html", html);
    return pictures;
}

}  // namespace shadowlab
