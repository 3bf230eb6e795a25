#include "gui/plot_panel.hpp"

#include <QComboBox>
#include <QDir>
#include <QLabel>
#include <QPixmap>
#include <QVBoxLayout>

#include "metrics/measurement.hpp"
#include "plot/shimmer_chart.hpp"

namespace shadowlab {
namespace {

ChartSpec error_against_resolution(const MeasureContext& context, const Method& method, const Settings& settings) {
    ChartSpec chart;
    chart.title = method.name + ": error against map resolution";
    chart.x_title = "map resolution (texels per side)";
    chart.y_title = "misclassified % / max perspective m (px)";
    chart.log_x = chart.log_y = true;
    ChartSeries wrong{"misclassified %", {}, {}, {}, true, {}, {}};
    // The perspective factor of m: the part a parameterization (and its resolution) controls; m's
    // own max is set by faces edge-on to the light, whatever the map.
    ChartSeries m{"max perspective m (texel width in pixels)", {}, {}, {}, true, {}, {}};
    for (int resolution : {256, 512, 1024, 2048}) {
        const Measurement r = measure(context, method, settings, resolution, -1.0);
        wrong.x.push_back(resolution), wrong.y.push_back(std::max(1e-3, 100.0 * r.error.misclassified));
        m.x.push_back(resolution), m.y.push_back(std::max(1e-3, r.error.m_perspective.max));
    }
    chart.series = {wrong, m};
    return chart;
}

}  // namespace

PlotPanel::PlotPanel(QWidget* parent) : QWidget(parent), kind_(new QComboBox(this)), image_(new QLabel(this)) {
    kind_->setObjectName("plotKind");
    kind_->addItem("Error against map resolution", static_cast<int>(Kind::error_against_resolution));
    kind_->addItem(QString("Shimmer: the camera moving sideways, %1 frames").arg(kShimmerFrames),
                   static_cast<int>(Kind::shimmer));
    image_->setAlignment(Qt::AlignCenter);
    image_->setMinimumSize(320, 200);
    image_->setScaledContents(false);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(kind_);
    layout->addWidget(image_, 1);
    connect(kind_, QOverload<int>::of(&QComboBox::activated), this, [this] { emit kindChosen(); });
}

PlotPanel::Kind PlotPanel::kind() const { return static_cast<Kind>(kind_->currentData().toInt()); }

void PlotPanel::set_kind(Kind kind) { kind_->setCurrentIndex(kind_->findData(static_cast<int>(kind))); }

QString PlotPanel::work(const std::string& method) const {
    return kind() == Kind::shimmer
               ? QString("plot: %1 along %2 frames of a sideways camera path").arg(QString::fromStdString(method)).arg(kShimmerFrames)
               : QString("plot: measuring %1 at 256² to 2048² against the exact reference").arg(QString::fromStdString(method));
}

bool PlotPanel::update_plot(const Scene& scene, const std::string& method_name,
                            const std::map<std::string, std::string>& overrides, int resolution) {
    const Method* method = find_method(method_name);
    if (!method || !method->makes_maps()) return false;
    const MeasureContext context = prepare_measurement(scene, kImageWidth, kImageWidth);
    const Settings settings = resolve_settings(method->name, method->settings, overrides);
    ChartSpec chart;
    if (kind() == Kind::shimmer) {
        const CameraPath path{CameraPath::Kind::translate, kShimmerFrames, 0.0};
        shimmer_ = measure_shimmer(context, shimmer_samples(context), *method, settings, resolution, -1.0, path);
        chart = shimmer_chart(*shimmer_, method_name + " at " + std::to_string(resolution) + "²: " + shimmer_summary(*shimmer_));
    } else {
        chart = error_against_resolution(context, *method, settings);
    }
    chart.width = 520;
    chart.height = 320;
    const QString file = QDir::temp().filePath("shadowlab-plot.png");
    write_chart_png(chart, file.toStdString());
    image_->setPixmap(QPixmap(file));
    return true;
}

}  // namespace shadowlab
