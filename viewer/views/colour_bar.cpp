// The colour bar hangs from the view's top-left corner (offsets in pixels, so that it stays there
// when the window is resized), below the legend's two rows: the ramp, its ticks below, the meaning of
// each side above.
#include "views/colour_bar.hpp"

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

namespace shadowlab {
namespace {

constexpr int kBarWidth = 300, kBarHeight = 10, kBarSteps = 96, kBarLeft = 8;
constexpr int kBarTop = 82;         // below the legend's two lines and the side labels' two
constexpr int kTitleBaseline = 16;  // the legend's first row

void hang_from_top_left(vtkCoordinate* position, vtkCoordinate* corner, double dx, double dy) {
    position->SetCoordinateSystemToDisplay();
    position->SetReferenceCoordinate(corner);
    position->SetValue(dx, dy);
}

vtkSmartPointer<vtkActor2D> ramp(const std::function<Rgb(double)>& colour_at) {
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
        const Rgb c = colour_at((i + 0.5) / kBarSteps);
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

}  // namespace

void add_colour_bar(vtkRenderer* renderer, const ColourBar& bar) {
    vtkNew<vtkCoordinate> corner;
    corner->SetCoordinateSystemToNormalizedViewport();
    corner->SetValue(0.0, 1.0);
    const double bottom = -kBarTop - kBarHeight;
    const auto place = [&](vtkActor2D* actor, double dx, double dy) {
        hang_from_top_left(actor->GetPositionCoordinate(), corner, dx, dy);
        renderer->AddViewProp(actor);
    };
    place(ramp(bar.ramp), kBarLeft, bottom);
    for (size_t k = 0; k < bar.ticks.size(); ++k) {
        const Anchor anchor = k == 0 ? Anchor::left : k + 1 == bar.ticks.size() ? Anchor::right : Anchor::centre;
        const double along = bar.ticks.size() > 1 ? kBarWidth * k / (bar.ticks.size() - 1.0) : 0.0;
        place(bar_label(bar.ticks[k], 11, anchor, false), kBarLeft + along, bottom - 2);
    }
    place(bar_label(bar.low_side, 12, Anchor::left, true), kBarLeft, -kBarTop + 2);
    place(bar_label(bar.high_side, 12, Anchor::right, true), kBarLeft + kBarWidth, -kBarTop + 2);
    if (!bar.title.empty()) place(bar_label(bar.title, 12, Anchor::left, true), kBarLeft, -kTitleBaseline);
}

}  // namespace shadowlab
