// A vtkChartXY in a vtkContextView, rendered offscreen, read back and written with vtkPNGWriter.
#include "plot/chart_png.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContext2D.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPen.h>
#include <vtkPlotPoints.h>
#include <vtkPoints2D.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include "render/rgb_image.hpp"
#include "render/x_display.hpp"

namespace shadowlab {
namespace {

using Rgb = std::array<unsigned char, 3>;
using Point = std::array<double, 2>;

// Texts beside the points of a series. A points plot that paints labels instead of markers, so
// that it follows the chart's axes (log scales included) exactly like the series it annotates.
class PointLabels : public vtkPlotPoints {
public:
    static PointLabels* New();
    vtkTypeMacro(PointLabels, vtkPlotPoints);

    std::vector<std::string> labels;
    Rgb rgb{};

    bool Paint(vtkContext2D* painter) override {
        if (!this->Visible || !this->Points) return false;
        vtkTextProperty* text = painter->GetTextProp();
        text->SetColor(rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0);
        text->SetFontSize(12);
        text->SetBold(false);
        text->SetJustificationToLeft();
        text->SetVerticalJustificationToBottom();
        const vtkIdType n = std::min<vtkIdType>(this->Points->GetNumberOfPoints(), labels.size());
        for (vtkIdType i = 0; i < n; ++i) {
            double p[2];
            this->Points->GetPoint(i, p);
            if (!labels[i].empty() && std::isfinite(p[0]) && std::isfinite(p[1]))
                painter->DrawString(static_cast<float>(p[0]), static_cast<float>(p[1]), " " + labels[i]);
        }
        return true;
    }
};
vtkStandardNewMacro(PointLabels);

vtkSmartPointer<vtkTable> make_table(const std::vector<Point>& points) {
    vtkNew<vtkDoubleArray> x, y;
    x->SetName("x");
    y->SetName("y");
    for (const Point& p : points) {
        x->InsertNextValue(p[0]);
        y->InsertNextValue(p[1]);
    }
    auto table = vtkSmartPointer<vtkTable>::New();
    table->AddColumn(x);
    table->AddColumn(y);
    return table;
}

vtkPlotPoints* add_plot(vtkChartXY& chart, int type, vtkTable* table, const Rgb& rgb, int marker, float size) {
    auto* plot = vtkPlotPoints::SafeDownCast(chart.AddPlot(type));  // LINE and POINTS are both vtkPlotPoints
    plot->SetInputData(table, 0, 1);
    plot->SetColor(rgb[0], rgb[1], rgb[2], 255);
    plot->SetWidth(2.0f);
    plot->SetMarkerStyle(marker);
    plot->SetMarkerSize(size);
    return plot;
}

// The range of the points drawn, per axis (x, y).
struct Bounds {
    Point lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
};

void add_series(vtkChartXY& chart, const ChartSpec& spec, size_t index, Bounds& bounds) {
    const ChartSeries& s = spec.series[index];
    const size_t n = s.x.size();
    if (s.y.size() != n || (!s.labels.empty() && s.labels.size() != n) || (!s.marked.empty() && s.marked.size() != n))
        throw std::runtime_error("chart series '" + s.name + "': x, y, labels and marked differ in length");

    std::vector<Point> kept, marked;
    std::vector<std::string> labels;
    size_t dropped = 0;
    for (size_t i = 0; i < n; ++i) {
        if ((spec.log_x && !(s.x[i] > 0)) || (spec.log_y && !(s.y[i] > 0))) {
            ++dropped;
            continue;
        }
        kept.push_back({s.x[i], s.y[i]});
        for (int a = 0; a < 2; ++a) {
            bounds.lo[a] = std::min(bounds.lo[a], kept.back()[a]);
            bounds.hi[a] = std::max(bounds.hi[a], kept.back()[a]);
        }
        if (!s.labels.empty()) labels.push_back(s.labels[i]);
        if (!s.marked.empty() && s.marked[i]) marked.push_back({s.x[i], s.y[i]});
    }

    const Rgb rgb = series_color(spec, index);
    vtkSmartPointer<vtkTable> table = make_table(kept);
    const bool line = s.line && kept.size() >= 2;  // a line needs two points; one is drawn as a point
    vtkPlotPoints* plot = add_plot(chart, line ? vtkChart::LINE : vtkChart::POINTS, table, rgb, vtkPlotPoints::CIRCLE,
                                   line ? 6.0f : 8.0f);
    plot->SetLabel(dropped == 0 ? s.name : s.name + " (" + std::to_string(dropped) + " non-positive dropped)");
    plot->SetLegendVisibility(s.in_legend);
    if (s.dashed) plot->GetPen()->SetLineType(vtkPen::DASH_LINE);
    if (!marked.empty())
        add_plot(chart, vtkChart::POINTS, make_table(marked), rgb, vtkPlotPoints::CROSS, 16.0f)
            ->SetLegendVisibility(false);
    if (!labels.empty()) {
        vtkNew<PointLabels> text;
        text->labels = std::move(labels);
        text->rgb = rgb;
        text->SetInputData(table, 0, 1);
        text->SetLegendVisibility(false);
        chart.AddPlot(text);
    }
}

// A fixed range 4 % wider than the data on each side (in log space on a log axis), so that markers
// at the ends are not cut; VTK's automatic range ends exactly at the data.
void pad_axis(vtkAxis* axis, double lo, double hi, bool log) {
    if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi)) return;
    if (log) {
        const double margin = 0.04 * std::max(std::log10(hi / lo), 0.5);
        axis->SetUnscaledRange(lo / std::pow(10.0, margin), hi * std::pow(10.0, margin));
    } else {
        const double margin = 0.04 * (hi > lo ? hi - lo : std::max(std::abs(lo), 1.0));
        axis->SetUnscaledRange(lo - margin, hi + margin);
    }
    axis->SetBehavior(vtkAxis::FIXED);
}

}  // namespace

std::array<unsigned char, 3> palette_color(size_t index) {
    // Tableau's ten, then four more far from them (bench --filters draws eleven families).
    static constexpr std::array<Rgb, 14> palette{{{31, 119, 180},
                                                  {255, 127, 14},
                                                  {44, 160, 44},
                                                  {214, 39, 40},
                                                  {148, 103, 189},
                                                  {140, 86, 75},
                                                  {227, 119, 194},
                                                  {127, 127, 127},
                                                  {188, 189, 34},
                                                  {23, 190, 207},
                                                  {30, 30, 30},
                                                  {0, 100, 60},
                                                  {120, 0, 90},
                                                  {230, 180, 0}}};
    return palette[index % palette.size()];
}

std::array<unsigned char, 3> series_color(const ChartSpec& chart, size_t index) {
    const Rgb& own = chart.series.at(index).color;
    return own == Rgb{0, 0, 0} ? palette_color(index) : own;
}

void write_chart_png(const ChartSpec& spec, const std::string& png_file) {
    if (spec.width <= 0 || spec.height <= 0)
        throw std::runtime_error("chart '" + spec.title + "': width and height must be positive");
    vtkNew<vtkChartXY> chart;
    chart->SetTitle(spec.title);
    chart->SetShowLegend(true);
    using Corner = ChartSpec::LegendCorner;
    const bool left = spec.legend == Corner::top_left || spec.legend == Corner::bottom_left;
    const bool bottom = spec.legend == Corner::bottom_left || spec.legend == Corner::bottom_right;
    chart->GetLegend()->SetHorizontalAlignment(left ? vtkChartLegend::LEFT : vtkChartLegend::RIGHT);
    chart->GetLegend()->SetVerticalAlignment(bottom ? vtkChartLegend::BOTTOM : vtkChartLegend::TOP);
    chart->GetAxis(vtkAxis::BOTTOM)->SetTitle(spec.x_title);
    chart->GetAxis(vtkAxis::LEFT)->SetTitle(spec.y_title);
    chart->GetAxis(vtkAxis::BOTTOM)->SetLogScale(spec.log_x);
    chart->GetAxis(vtkAxis::LEFT)->SetLogScale(spec.log_y);
    Bounds bounds;
    for (size_t i = 0; i < spec.series.size(); ++i) add_series(*chart, spec, i, bounds);
    pad_axis(chart->GetAxis(vtkAxis::BOTTOM), bounds.lo[0], bounds.hi[0], spec.log_x);
    pad_axis(chart->GetAxis(vtkAxis::LEFT), bounds.lo[1], bounds.hi[1], spec.log_y);

    const XDisplay x("plots");  // before VTK would open one
    if (!std::ofstream(png_file, std::ios::binary)) throw std::runtime_error("cannot write the chart to " + png_file);

    vtkNew<vtkContextView> view;
    view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
    view->GetScene()->AddItem(chart);
    vtkRenderWindow* window = view->GetRenderWindow();
    // No interactor: initializing one syncs with an X window an offscreen render never maps, and
    // that crashed now and then in XSync under Xvfb.
    window->SetInteractor(nullptr);
    window->SetDisplayId(x.handle());
    window->SetOffScreenRendering(1);
    window->SetSize(spec.width, spec.height);
    window->Render();

    write_png(grab(window), png_file);
}

}  // namespace shadowlab
