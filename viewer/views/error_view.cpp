// The Error view: the camera image measured against the exact reference. Misclassified pixels are
// painted by kind (error_colours.hpp: false shadow blue, false light green, each grown to a 3x3 block
// so that a lone pixel is seen) and named in a legend. For a map the other receiver pixels show
// Lloyd's m, or the factor of it the options choose, as a heat map (log scale, 1/8 to 8, its colour
// bar at the top right), judged with the inspection's bias (slope-scaled per pixel unless a constant
// was chosen); a geometric technique has no texels, so its agreeing pixels are light grey where lit
// and dark grey where shadowed. Where no surface is seen, a neutral mid grey.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include <vtkActor2D.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCoordinate.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include "metrics/shadow_error.hpp"
#include "reference/exact_shadows.hpp"
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

Rgb pixel_colour(const ShadowError& e, const ReferenceImage& ref, const std::vector<float>& heat_image, bool has_map,
                 size_t i) {
    if (e.verdicts[i] == PixelVerdict::agree) {
        if (has_map) return heat(heat_position(heat_image[i]));
        return ref.lit[i] ? colours::kAgreeLit : colours::kAgreeShadowed;
    }
    return ref.visible[i] ? colours::kNotJudged : colours::kNotVisible;
}

// Each misclassified pixel as a 3x3 block of its kind's colour; false light drawn last, on top.
void mark_misclassified(RgbImage& image, const ShadowError& e) {
    for (const auto& [kind, colour] : {std::pair{PixelVerdict::false_shadow, colours::kFalseShadow},
                                       std::pair{PixelVerdict::false_light, colours::kFalseLight}})
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                if (e.verdicts[static_cast<size_t>(y) * image.width + x] != kind) continue;
                for (int ny = std::max(0, y - 1); ny <= std::min(image.height - 1, y + 1); ++ny)
                    for (int nx = std::max(0, x - 1); nx <= std::min(image.width - 1, x + 1); ++nx)
                        std::copy(colour.begin(), colour.end(), image.at(nx, ny));
            }
}

RgbImage paint(const ShadowError& e, const ReferenceImage& ref, const std::vector<float>& heat_image, bool has_map) {
    RgbImage image(ref.width, ref.height);
    for (size_t i = 0; i < ref.visible.size(); ++i) {
        const Rgb c = pixel_colour(e, ref, heat_image, has_map, i);
        std::copy(c.begin(), c.end(), image.rgb.begin() + 3 * i);
    }
    mark_misclassified(image, e);
    return image;
}

glm::dvec3 unit_colour(const error_colours::Colour& c) { return glm::dvec3(c[0], c[1], c[2]) / 255.0; }

void add_misclassified_legend(vtkRenderer* renderer) {
    add_legend(renderer, {{unit_colour(colours::kFalseShadow), "false shadow (acne)"},
                          {unit_colour(colours::kFalseLight), "false light (leak)"}});
}

// The colour bar, hung from the view's top-left corner below the legend (offsets in pixels, so that
// it stays there when the window is resized): the ramp, its ticks below, the meaning of each side
// above (two lines each).
constexpr int kBarWidth = 300, kBarHeight = 10, kBarSteps = 96, kBarLeft = 8;
constexpr int kBarTop = 82;  // below the legend's two lines and the side labels' two

void hang_from_top_left(vtkCoordinate* position, vtkCoordinate* corner, double dx, double dy) {
    position->SetCoordinateSystemToDisplay();
    position->SetReferenceCoordinate(corner);
    position->SetValue(dx, dy);
}

vtkSmartPointer<vtkActor2D> ramp() {
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> quads;
    vtkNew<vtkUnsignedCharArray> colour;
    colour->SetNumberOfComponents(3);
    for (int i = 0; i < kBarSteps; ++i) {
        const double x0 = kBarWidth * static_cast<double>(i) / kBarSteps, x1 = kBarWidth * (i + 1.0) / kBarSteps;
        const vtkIdType first = points->GetNumberOfPoints();
        for (const auto& [x, y] : {std::pair{x0, 0.0}, {x1, 0.0}, {x1, double(kBarHeight)}, {x0, double(kBarHeight)}})
            points->InsertNextPoint(x, y, 0.0);
        const vtkIdType ids[4] = {first, first + 1, first + 2, first + 3};
        quads->InsertNextCell(4, ids);
        const Rgb c = heat((i + 0.5) / kBarSteps);
        colour->InsertNextTuple3(c[0], c[1], c[2]);
    }
    vtkNew<vtkPolyData> data;
    data->SetPoints(points);
    data->SetPolys(quads);
    data->GetCellData()->SetScalars(colour);
    vtkNew<vtkPolyDataMapper2D> mapper;
    mapper->SetInputData(data);
    mapper->SetScalarModeToUseCellData();
    mapper->SetColorModeToDirectScalars();
    auto actor = vtkSmartPointer<vtkActor2D>::New();
    actor->SetMapper(mapper);
    return actor;
}

enum class Anchor { left, centre, right };

vtkSmartPointer<vtkTextActor> bar_label(const std::string& text, int font_size, Anchor anchor, bool above) {
    auto label = vtkSmartPointer<vtkTextActor>::New();
    label->SetInput(text.c_str());
    vtkTextProperty* style = label->GetTextProperty();
    style_overlay_text(style, font_size);
    if (anchor == Anchor::left) style->SetJustificationToLeft();
    if (anchor == Anchor::centre) style->SetJustificationToCentered();
    if (anchor == Anchor::right) style->SetJustificationToRight();
    if (above)
        style->SetVerticalJustificationToBottom();
    else
        style->SetVerticalJustificationToTop();
    return label;
}

void add_colour_bar(vtkRenderer* renderer, const char* quantity) {
    vtkNew<vtkCoordinate> corner;
    corner->SetCoordinateSystemToNormalizedViewport();
    corner->SetValue(0.0, 1.0);
    const double bottom = -kBarTop - kBarHeight;
    const auto place = [&](vtkActor2D* actor, double dx, double dy) {
        hang_from_top_left(actor->GetPositionCoordinate(), corner, dx, dy);
        renderer->AddViewProp(actor);
    };
    place(ramp(), kBarLeft, bottom);
    const std::array<const char*, 7> ticks{"1/8", "1/4", "1/2", "1", "2", "4", "8"};
    for (size_t k = 0; k < ticks.size(); ++k) {
        const Anchor anchor = k == 0 ? Anchor::left : k + 1 == ticks.size() ? Anchor::right : Anchor::centre;
        place(bar_label(ticks[k], 11, anchor, false), kBarLeft + kBarWidth * k / (ticks.size() - 1.0), bottom - 2);
    }
    const std::string q = quantity;
    place(bar_label("over-sampled (" + q + " < 1):\ntexel smaller than pixel", 12, Anchor::left, true), kBarLeft,
          -kBarTop + 2);
    place(bar_label("under-sampled (" + q + " > 1):\ntexel larger than pixel", 12, Anchor::right, true),
          kBarLeft + kBarWidth, -kBarTop + 2);
}

std::string shares(const ShadowError& e) {
    char text[160];
    std::snprintf(text, sizeof text, "%.3f%% misclassified (false shadow %.3f%%, false light %.3f%%)",
                  100 * e.misclassified, 100 * e.false_shadow, 100 * e.false_light);
    return text;
}

}  // namespace

ViewReport build_error_view(vtkRenderer* renderer, const Inspection& in, const ViewOptions& options) {
    const glm::dvec3 background = unit_colour(colours::kNotVisible);
    renderer->SetBackground(background.r, background.g, background.b);
    // A technique is judged on the image it ran on; a map on an image of the panel's size.
    const int width = !in.has_map() ? in.image_width : options.width > 0 ? options.width : 640;
    const int height = !in.has_map()        ? in.image_height
                       : options.height > 0 ? options.height
                                            : std::max(1, static_cast<int>(std::lround(width / in.scene.camera.aspect)));
    const ReferenceImage& ref = in.reference(width, height);
    const ShadowError& e = in.error(width, height);
    const Shown aliasing = shown(e, options.aliasing);
    show_image(renderer, paint(e, ref, aliasing.image, in.has_map()));
    add_misclassified_legend(renderer);
    if (!in.has_map()) {
        add_caption(renderer, "Error — " + in.name() + ": " + shares(e) + "; agreeing pixels grey (light: lit)");
        return {};
    }
    add_colour_bar(renderer, aliasing.name);
    char caption[160];
    std::snprintf(caption, sizeof caption, "; %s max %.2f, p95 %.2f", aliasing.name, aliasing.stats.max,
                  aliasing.stats.p95);
    add_caption(renderer, "Error — " + in.name() + " " + std::to_string(in.resolution) + "²: " + shares(e) + caption);
    return {};
}

}  // namespace shadowlab
