#include "lesson_command.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "interactive_lesson.hpp"
#include "lesson_page.hpp"
#include "limits.hpp"
#include "flatland/texel_density.hpp"
#include "plot/density_chart.hpp"
#include "views/offscreen_view.hpp"
#include "what_goes_wrong.hpp"

namespace shadowlab {
namespace {

std::string picture_file(size_t step, const Picture& p) {
    char name[96];
    std::snprintf(name, sizeof name, "step-%02zu-%s-%s.png", step + 1, p.view->name.c_str(), to_string(p.preset));
    return name;
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
    if (in.has_map()) {
        html += texels_along_the_view(in, o, dir);
        pictures += 2;
    }
    html += what_goes_wrong(in, o, beside_page);
    ++pictures;
    html += "</body></html>\n";
    write_text_file(dir / "index.html", html);
    return pictures;
}

}  // namespace shadowlab
