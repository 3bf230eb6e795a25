#include "lesson_page.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include "scene/image_size.hpp"
#include "scene/scene_loader.hpp"

namespace shadowlab {
namespace {

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

const char* kStyle = R"(
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
)";

// <!DOCTYPE html> to <body>: the title and the pages' shared style sheet with `style` added.
std::string document_start(const std::string& title, const std::string& style) {
    return "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" + html_escaped(title) + "</title><style>" +
           kStyle + style + "</style></head><body>\n";
}

}  // namespace

Inspection inspect_for_lesson(const LessonOptions& o) {
    const Scene scene = load_scene_source(o.scene_file, o.scene_source);
    const glm::ivec2 camera_image = image_size_within(scene.camera, o.width, o.height);
    return inspect_scene(scene, {.method = o.method,
                                 .settings = o.settings,
                                 .resolution = o.resolution,
                                 .image_width = camera_image.x,
                                 .image_height = camera_image.y});
}

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

glm::ivec2 picture_size(const Inspection& in, const Picture& picture, const LessonOptions& o) {
    return picture.view->interaction.through_scene_camera ? image_size_within(in.scene.camera, o.width, o.height)
                                                          : glm::ivec2(o.width, o.height);
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

std::string picture_figure(const std::string& src, int width, const std::string& caption) {
    return "<figure><img src=\"" + src + "\" width=\"" + std::to_string(width) + "\" alt=\"" + html_escaped(caption) +
           "\"><figcaption>" + html_escaped(caption) + "</figcaption></figure>";
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

std::string step_heading(const Step& step, size_t i, size_t count, MatrixLayout layout) {
    return "<h2>Step " + std::to_string(i + 1) + " of " + std::to_string(count) + ": " + html_escaped(step.title) +
           "</h2>\n<p class=\"formula\">" + html_escaped(step.explanation) +
           "</p>\n<p>Space: " + to_string(step.space) + "</p>\n" + values_table(step, layout) + "\n";
}

std::string page_head(const Inspection& in, const LessonOptions& o, MatrixLayout layout, const std::string& style) {
    return document_start(in.title() + " step by step", style) + "<h1>" + html_escaped(in.title()) +
           " step by step</h1>\n<p>" + html_escaped(in.method->description) + "</p>\n<p>Scene <code>" +
           html_escaped(o.scene_file) + "</code>, " + (in.has_map() ? std::to_string(in.resolution) + "² map. " : "") +
           "Matrices in " + layout_note(layout) + "; hover a matrix entry for all its digits.</p>\n" +
           (in.notes().empty() ? ""
                               : "<p><b>" + std::string(in.has_map() ? "Fallback" : "Limits") + ":</b> " +
                                     html_escaped(describe(in.notes())) + "</p>\n");
}

std::string lesson_page(const std::string& title, const std::string& body) {
    return document_start(title, "") + body + "</body></html>\n";
}

void write_text_file(const std::filesystem::path& file, const std::string& text) {
    std::ofstream page(file);
    page << text;
    if (!page) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace shadowlab
