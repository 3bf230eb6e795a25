#include "lesson_command.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "io/value_text.hpp"
#include "limits.hpp"
#include "flatland/texel_density.hpp"
#include "metrics/diagnosis.hpp"
#include "plot/density_chart.hpp"
#include "scene/image_size.hpp"
#include "scene/scene_loader.hpp"
#include "views/offscreen_view.hpp"
#include "views/space_parts.hpp"

namespace shadowlab {
namespace {

struct Picture {
    const View* view;
    SpacePreset preset;
    std::string title;  // what the picture shows, under it
};

bool has_space(const Inspection& in, Space space) { return static_cast<bool>(in.trace.frame(space)); }

// The view in which the method's own space is drawn: PPLS when the method warps or its unit space
// is an atlas (paraboloids, a tetrahedron's faces: the PPLS view draws the atlas), Light space when
// it only fits a box (uniform, focused), the World view for a geometric technique.
const View& view_of(const Inspection& in, Space space) {
    if (space == Space::world || space == Space::view) return view_or_throw("world");
    if (space == Space::ppls || space == Space::unit)
        return view_or_throw(has_space(in, Space::ppls) || unit_space_is_an_atlas(in, space) ? "ppls"
                             : has_space(in, Space::light)                                   ? "light"
                                                                                             : "world");
    return view_or_throw(has_space(in, Space::light) ? "light" : "world");
}

// The pictures that show step `i`: its space from the side and from the light (an orbit for the
// world), both sides of the warp at the first step in PPLS, and the result after the last step.
std::vector<Picture> pictures_of(const Inspection& in, size_t i) {
    const std::vector<Step>& steps = in.trace.steps();
    const View& view = view_of(in, steps[i].space);
    const View& ppls = view_or_throw("ppls");
    std::vector<Picture> out;
    if (view == view_or_throw("world")) {
        out.push_back({&view, SpacePreset::orbit, "World"});
    } else if (view == ppls && !has_space(in, Space::ppls)) {  // an atlas, seen straight on from any preset
        out.push_back({&view, SpacePreset::orbit, "PPLS: the atlas"});
    } else {
        const bool warp_applied =
            view == ppls && std::none_of(steps.begin(), steps.begin() + i,
                                         [&](const Step& earlier) { return view_of(in, earlier.space) == ppls; });
        if (warp_applied)
            out.push_back({&view_or_throw("light"), SpacePreset::side, "before the warp: Light space, side"});
        out.push_back(
            {&view, SpacePreset::side, std::string(warp_applied ? "after the warp: " : "") + view.title + ", side"});
        out.push_back({&view, SpacePreset::from_light, view.title + ", from the light"});
    }
    if (i + 1 == steps.size()) {
        out.push_back({&view_or_throw("camera"), SpacePreset::orbit, "Camera: the shadows"});
        out.push_back({&view_or_throw(in.has_map() ? "shadowmap" : "stencil"), SpacePreset::orbit,
                       in.has_map() ? "Shadow map" : "Stencil count"});
        out.push_back({&view_or_throw("error"), SpacePreset::orbit, "Error against the exact reference"});
    }
    return out;
}

std::string html_escaped(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

// A matrix as a 4 x 4 table: 4 significant digits shown, all 17 on hover.
std::string matrix_table(const glm::dmat4& m, MatrixLayout layout) {
    const MatrixCells shown = matrix_cells(m, layout, kReadableDigits), exact = matrix_cells(m, layout, kFullDigits);
    std::string out = "<table class=\"matrix\">";
    for (int r = 0; r < 4; ++r) {
        out += "<tr>";
        for (int c = 0; c < 4; ++c) out += "<td title=\"" + exact[r][c] + "\">" + shown[r][c] + "</td>";
        out += "</tr>";
    }
    return out + "</table>";
}

std::string values_table(const Step& step, MatrixLayout layout) {
    if (step.values.empty()) return "";
    std::string out = "<table class=\"values\">";
    for (const NamedValue& v : step.values) {
        const auto* m = std::get_if<glm::dmat4>(&v.value);
        out += "<tr><th>" + html_escaped(v.name) + "</th><td>" +
               (m ? matrix_table(*m, layout) : "<code>" + html_escaped(value_text(v.value)) + "</code>") + "</td></tr>";
    }
    return out + "</table>";
}

std::string picture_file(size_t step, const Picture& p) {
    char name[96];
    std::snprintf(name, sizeof name, "step-%02zu-%s-%s.png", step + 1, p.view->name.c_str(), to_string(p.preset));
    return name;
}

const char* kStyle = R"(<style>
body { font-family: sans-serif; max-width: 1400px; margin: 2em auto; color: #222; }
section { border-top: 1px solid #ccc; padding: 0.5em 0 1.5em; }
.formula { font-family: monospace; background: #f4f4f4; padding: 0.3em 0.5em; }
table.values th { text-align: left; padding-right: 1em; vertical-align: top; font-weight: normal; font-family: monospace; }
table.matrix { border-left: 2px solid #444; border-right: 2px solid #444; font-family: monospace; }
table.matrix td { text-align: right; padding: 0 0.6em; }
figure { display: inline-block; margin: 0.5em 0.5em 0 0; }
figure img { display: block; border: 1px solid #ccc; }
figcaption { font-size: 90%; color: #555; }
table.causes { border-collapse: collapse; margin: 0.5em 0; }
table.causes th, table.causes td { border-bottom: 1px solid #ddd; padding: 0.2em 0.6em; text-align: left; vertical-align: top; }
table.causes td.number { text-align: right; white-space: nowrap; }
.swatch { display: inline-block; width: 0.9em; height: 0.9em; margin-right: 0.4em; vertical-align: -0.1em; border: 1px solid #888; }
</style>)";

std::string page_head(const Inspection& in, const LessonOptions& o, MatrixLayout layout) {
    return "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" + html_escaped(in.title()) +
           " step by step</title>" + kStyle + "</head><body>\n<h1>" + html_escaped(in.title()) +
           " step by step</h1>\n<p>" + html_escaped(in.method->description) + "</p>\n<p>Scene <code>" +
           html_escaped(o.scene_file) + "</code>, " + (in.has_map() ? std::to_string(in.resolution) + "² map. " : "") +
           "Matrices in " + layout_note(layout) + "; hover a matrix entry for all its digits.</p>\n" +
           (in.notes().empty() ? ""
                               : "<p><b>" + std::string(in.has_map() ? "Fallback" : "Limits") + ":</b> " +
                                     html_escaped(describe(in.notes())) + "</p>\n");
}

Inspection inspect_for_lesson(const LessonOptions& o) {
    const Scene scene = load_scene_source(o.scene_file, o.scene_source);
    const glm::ivec2 camera_image = image_size_within(scene.camera, o.width, o.height);
    return inspect_scene(scene, {.method = o.method,
                                 .settings = o.settings,
                                 .resolution = o.resolution,
                                 .image_width = camera_image.x,
                                 .image_height = camera_image.y});
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

// "Texels along the view": the Flatland view (every k-th texel boundary in the plane of the view
// and the light) and the map's texels per unit of view depth against the ideal, for an image as
// tall as the map is wide. Two pictures; none for a technique, which has no texels.
std::string texels_along_the_view(const Inspection& in, const LessonOptions& o, const std::filesystem::path& dir) {
    const char *flatland_file = "texels-along-the-view-flatland.png", *chart_file = "texels-along-the-view-density.png";
    write_png(render_view(in, view_or_throw("flatland"), {}, o.width, o.height), (dir / flatland_file).string());
    ChartSpec chart = density_chart(texel_density_over_view(in.inputs, in.setup, in.resolution, in.resolution),
                                    in.name(), in.resolution, in.resolution);
    chart.width = o.width, chart.height = o.height;
    write_chart_png(chart, (dir / chart_file).string());
    const std::string width = std::to_string(o.width);
    return "<section id=\"texels-along-the-view\"><h2>Texels along the view</h2>\n<p>In the plane of the view "
           "and the light (Lloyd et al. 2008's flatland), the map's texel boundaries as lines in the world: where "
           "they crowd, the map spends its texels. Beside it, texels per unit of view depth along the view axis "
           "against the ideal H / (2 z tan(θ/2)), at which a texel is as long as a pixel's footprint (the "
           "perspective factor of m is 1).</p>\n<figure><img src=\"" +
           std::string(flatland_file) + "\" width=\"" + width +
           "\" alt=\"Flatland\"><figcaption>Flatland: the texel boundaries, the frustum, B and the map's "
           "volume</figcaption></figure><figure><img src=\"" +
           chart_file + "\" width=\"" + width +
           "\" alt=\"Texel density\"><figcaption>Texels per unit of view depth, the method's against the "
           "ideal</figcaption></figure></section>\n";
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
    std::string html = page_head(in, o, layout);
    const std::vector<Step>& steps = in.trace.steps();
    int pictures = 0;
    for (size_t i = 0; i < steps.size(); ++i) {
        const Step& step = steps[i];
        html += "<section id=\"" + html_escaped(step.id) + "\"><h2>Step " + std::to_string(i + 1) + " of " +
                std::to_string(steps.size()) + ": " + html_escaped(step.title) + "</h2>\n<p class=\"formula\">" +
                html_escaped(step.explanation) + "</p>\n<p>Space: " + to_string(step.space) + "</p>\n" +
                values_table(step, layout) + "\n<div>";
        for (const Picture& p : pictures_of(in, i)) {
            const std::string file = picture_file(i, p);
            const glm::ivec2 size = p.view->interaction.through_scene_camera
                                        ? image_size_within(in.scene.camera, o.width, o.height)
                                        : glm::ivec2(o.width, o.height);
            write_png(render_view(in, *p.view, {.step = step.id, .preset = p.preset}, size.x, size.y),
                      (dir / file).string());
            ++pictures;
            html += "<figure><img src=\"" + file + "\" width=\"" + std::to_string(size.x) + "\" alt=\"" +
                    html_escaped(p.title) + "\"><figcaption>" + html_escaped(p.title) + "</figcaption></figure>";
        }
        html += "</div></section>\n";
    }
    if (in.has_map()) {
        html += texels_along_the_view(in, o, dir);
        pictures += 2;
    }
    html += what_goes_wrong(in, o, dir);
    ++pictures;
    html += "</body></html>\n";
    std::ofstream page(dir / "index.html");
    page << html;
    if (!page) throw std::runtime_error("cannot write " + (dir / "index.html").string());
    return pictures;
}

}  // namespace shadowlab
