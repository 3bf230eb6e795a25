#include "interactive_lesson.hpp"

#include <unordered_map>

#include <nlohmann/json.hpp>

#include "lesson_script.hpp"
#include "views/offscreen_view.hpp"
#include "views/view_export.hpp"
#include "what_goes_wrong.hpp"

namespace shadowlab {
namespace {

using nlohmann::json;

const char* kStyle = R"(
body { max-width: none; margin: 1em 2em; }
.lesson { display: flex; gap: 1.5em; align-items: flex-start; }
#steps { flex: 0 0 16em; display: flex; flex-direction: column; gap: 0.2em; position: sticky; top: 1em; }
#steps button { text-align: left; font: inherit; padding: 0.3em 0.5em; border: 1px solid #ccc; background: #fafafa; cursor: pointer; }
#steps button.active { background: #2a4d7a; color: #fff; border-color: #2a4d7a; }
section.step { border-top: none; padding-top: 0; }
.orbit { position: relative; border: 1px solid #ccc; cursor: grab; }
.orbit canvas { display: block; }
.labels, .legend { position: absolute; top: 0; left: 0; pointer-events: none; }
.legend { padding: 4px 8px; display: flex; flex-wrap: wrap; gap: 2px 14px; font: 12px 'DejaVu Sans', sans-serif; color: #ebebeb; }
.legend > span { background: rgba(0, 0, 0, 0.45); padding: 0 0.2em; }
.legend .swatch { display: inline-block; width: 14px; height: 5px; margin-right: 5px; vertical-align: middle; }
.label span { font: 14px 'DejaVu Sans', sans-serif; background: rgba(0, 0, 0, 0.45); padding: 0 0.2em; white-space: nowrap; }
)";

// RFC 4648 base64, for pictures inlined as data URIs.
std::string base64(const std::string& bytes) {
    static const char* const kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const size_t n = std::min<size_t>(3, bytes.size() - i);
        unsigned group = 0;
        for (size_t k = 0; k < 3; ++k) group = group << 8 | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
        for (size_t k = 0; k < 4; ++k) out += k <= n ? kDigits[group >> (18 - 6 * k) & 63] : '=';
    }
    return out;
}

// JSON inside a <script> element: "</" is written "<\/" (the same string) so that no "</script>"
// in a label ends the element early.
std::string script_safe(const json& data) {
    std::string out;
    for (char c : data.dump()) {
        if (c == '/' && !out.empty() && out.back() == '<') out += '\\';
        out += c;
    }
    return out;
}

// The views' coordinate and colour arrays, each stored once: the scene's triangles recur in the
// views of many steps. {"arrays": [...], "views": the views, each array of a shape longer than one
// point replaced by {"pooled": its index in "arrays"}} (web/src/lesson.js puts them back).
json pooled(json views) {
    json arrays = json::array();
    std::unordered_map<std::string, size_t> index;
    for (json& view : views)
        for (json& shape : view["shapes"])
            for (auto& [key, value] : shape.items()) {
                if (!value.is_array() || value.size() <= 3) continue;
                const auto [at, added] = index.try_emplace(value.dump(), arrays.size());
                if (added) arrays.push_back(std::move(value));
                value = json{{"pooled", at->second}};
            }
    return {{"arrays", std::move(arrays)}, {"views", std::move(views)}};
}

// A picture inlined in the page as a PNG data URI.
std::string inlined(const RgbImage& image, const std::string&) {
    return "data:image/png;base64," + base64(png_bytes(image));
}

// A step's picture on the page: a view that draws the trace's steps as its scene to orbit (its
// index in `scenes`), any other as its rendered PNG.
std::string picture_html(const Inspection& in, const Step& step, const Picture& p, const LessonOptions& o,
                         json& scenes) {
    const glm::ivec2 size = picture_size(in, p, o);
    const ViewOptions options{.step = step.id, .preset = p.preset};
    const std::string width = std::to_string(size.x) + "px", height = std::to_string(size.y) + "px";
    if (p.view->interaction.draws_steps) {
        scenes.push_back(exported_view(in, *p.view, options, size.x, size.y));
        return "<figure><div class=\"orbit\" data-scene=\"" + std::to_string(scenes.size() - 1) +
               "\" style=\"width: " + width + "; height: " + height + "\"></div><figcaption>" + html_escaped(p.title) +
               " (drag to orbit, wheel to zoom)</figcaption></figure>";
    }
    return picture_figure(inlined(render_view(in, *p.view, options, size.x, size.y), ""), size.x, p.title);
}

}  // namespace

int write_interactive_lesson(const Inspection& in, const LessonOptions& o, MatrixLayout layout,
                             const std::filesystem::path& file) {
    const std::vector<Step>& steps = in.trace.steps();
    json scenes = json::array();
    std::string buttons, sections;
    int views = 0;
    for (size_t i = 0; i < steps.size(); ++i) {
        const Step& step = steps[i];
        const std::string id = html_escaped(step.id);
        buttons += "<button type=\"button\" data-step=\"" + id + "\">" + std::to_string(i + 1) + ". " +
                   html_escaped(step.title) + "</button>\n";
        sections += "<section class=\"step\" data-step=\"" + id + "\"" + (i > 0 ? " hidden" : "") + ">" +
                    step_heading(step, i, steps.size(), layout) + "<div>";
        for (const Picture& p : pictures_of(in, i)) {
            sections += picture_html(in, step, p, o, scenes);
            ++views;
        }
        sections += "</div></section>\n";
    }
    sections += what_goes_wrong(in, o, inlined);  // below every step, its Error view by cause
    ++views;
    write_text_file(file, page_head(in, o, layout, kStyle) + "<div class=\"lesson\"><nav id=\"steps\">\n" + buttons +
                              "</nav><main>\n" + sections + "</main></div>\n<pre id=\"selftest\" hidden></pre>\n" +
                              "<script type=\"application/json\" id=\"lesson-scenes\">" +
                              script_safe(pooled(std::move(scenes))) + "</script>\n<script>" +
                              std::string(lesson_script()) + "</script>\n</body></html>\n");
    return views;
}

}  // namespace shadowlab
