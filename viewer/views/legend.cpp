// A view's legend: a colour swatch and its meaning per entry, flowing left to right from the
// top-left corner and on to the next row where the renderer's width ends (laid out again at each
// render, as the window is resized), so that it takes a few rows, not a column over the picture;
// the caption keeps the bottom.
#include <vtkActor2D.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkCoordinate.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty2D.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>

#include "views/space_parts.hpp"

namespace shadowlab {
namespace {

constexpr int kLineHeight = 16, kFontSize = 12, kIndent = 8, kGap = 14;
constexpr int kSwatchWidth = 14, kSwatchHeight = 5, kSwatchGap = 5;  // a short thick bar, like the lines it stands for

void hang_from_top_left(vtkCoordinate* position, vtkCoordinate* corner, double dx, double dy) {
    position->SetCoordinateSystemToDisplay();
    position->SetReferenceCoordinate(corner);
    position->SetValue(dx, dy);
}

vtkSmartPointer<vtkActor2D> swatch(const glm::dvec3& colour) {
    vtkNew<vtkPoints> points;
    for (const auto& [x, y] : {std::pair{0, 0}, {kSwatchWidth, 0}, {kSwatchWidth, kSwatchHeight}, {0, kSwatchHeight}})
        points->InsertNextPoint(x, y, 0.0);
    vtkNew<vtkCellArray> quad;
    const vtkIdType ids[4] = {0, 1, 2, 3};
    quad->InsertNextCell(4, ids);
    vtkNew<vtkPolyData> data;
    data->SetPoints(points);
    data->SetPolys(quad);
    vtkNew<vtkPolyDataMapper2D> mapper;
    mapper->SetInputData(data);
    auto actor = vtkSmartPointer<vtkActor2D>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(colour.r, colour.g, colour.b);
    return actor;
}

vtkSmartPointer<vtkTextActor> entry_text(const std::string& text) {
    auto actor = vtkSmartPointer<vtkTextActor>::New();
    actor->SetInput(text.c_str());
    style_overlay_text(actor->GetTextProperty(), kFontSize, glm::dvec3(0.92));
    return actor;
}

// Places the entries in rows at the start of each render, as a typesetter fills lines.
class LegendFlow : public vtkCommand {
public:
    static LegendFlow* New() { return new LegendFlow; }
    vtkSmartPointer<vtkCoordinate> corner;
    std::vector<std::pair<vtkSmartPointer<vtkActor2D>, vtkSmartPointer<vtkTextActor>>> entries;

    void Execute(vtkObject* caller, unsigned long, void*) override {
        auto* renderer = static_cast<vtkRenderer*>(caller);
        const int width = renderer->GetSize()[0];
        const int dpi = renderer->GetRenderWindow() ? renderer->GetRenderWindow()->GetDPI() : 72;
        int x = kIndent, row = 0;
        for (const auto& [bar, text] : entries) {
            int box[4] = {0, 0, 0, 0};
            vtkTextRenderer::GetInstance()->GetBoundingBox(text->GetTextProperty(), text->GetInput(), box, dpi);
            const int entry_width = kSwatchWidth + kSwatchGap + (box[1] - box[0] + 1);
            if (x > kIndent && x + entry_width > width - kIndent) x = kIndent, ++row;
            const double baseline = -static_cast<double>(row + 1) * kLineHeight;
            hang_from_top_left(bar->GetPositionCoordinate(), corner, x, baseline + 3);
            hang_from_top_left(text->GetPositionCoordinate(), corner, x + kSwatchWidth + kSwatchGap, baseline);
            x += entry_width + kGap;
        }
    }
};

}  // namespace

void add_legend(vtkRenderer* renderer, const std::vector<LegendEntry>& entries) {
    vtkNew<LegendFlow> flow;
    flow->corner = vtkSmartPointer<vtkCoordinate>::New();
    flow->corner->SetCoordinateSystemToNormalizedViewport();
    flow->corner->SetValue(0.0, 1.0);
    for (const LegendEntry& e : entries) {
        flow->entries.emplace_back(swatch(e.colour), entry_text(e.text));
        renderer->AddViewProp(flow->entries.back().first);
        renderer->AddViewProp(flow->entries.back().second);
    }
    renderer->AddObserver(vtkCommand::StartEvent, flow);
}

}  // namespace shadowlab
