#include "lesson_command.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "interactive_lesson.hpp"
#include "lesson_page.hpp"
#include "limits.hpp"
#include "views/offscreen_view.hpp"
#include "what_goes_wrong.hpp"

namespace shadowlab {
namespace {

std::string picture_file(size_t step, const Picture& p) {
    char name[96];
    std::snprintf(name, sizeof name, "step-%02zu-%s-%s.png", step + 1, p.view->name.c_str(), to_string(p.preset));
    return name;
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
    const PictureSource beside_page = [&](const RgbImage& image, const std::string& name) {
        write_png(image, (dir / name).string());
        return name;
    };
    std::string html = page_head(in, o, layout);
    const std::vector<Step>& steps = in.trace.steps();
    int pictures = 0;
    for (size_t i = 0; i < steps.size(); ++i) {
        const Step& step = steps[i];
        html +=
            "<section id=\"" + html_escaped(step.id) + "\">" + step_heading(step, i, steps.size(), layout) + "<div>";
        for (const Picture& p : pictures_of(in, i)) {
            const glm::ivec2 size = picture_size(in, p, o);
            const RgbImage image = render_view(in, *p.view, {.step = step.id, .preset = p.preset}, size.x, size.y);
            html += picture_figure(beside_page(image, picture_file(i, p)), size.x, p.title);
            ++pictures;
        }
        html += "</div></section>\n";
    }
    html += what_goes_wrong(in, o, beside_page);
    ++pictures;
    html += "</body></html>\n";
    write_text_file(dir / "index.html", html);
    return pictures;
}

}  // namespace shadowlab
