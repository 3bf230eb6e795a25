#include "gui/plot_panel.hpp"

#include <QComboBox>
#include <QDir>
#include <QLabel>
#include <QPixmap>
#include <QVBoxLayout>

#include "metrics/bias_sweep.hpp"
#include "metrics/measurement.hpp"
#include "plot/bias_chart.hpp"
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

// The window's other settings held, bias_slope swept.
ChartSpec acne_against_bias(const MeasureContext& context, const Method& method,
                            std::map<std::string, std::string> settings, int resolution) {
    settings.erase("bias_slope");
    const BiasCurve curve = sweep_bias(context, method, settings, resolution, "bias_slope",
                                       default_bias_values(context, "bias_slope", resolution));
    ChartSpec chart = bias_chart({curve}, method.name + " at " + std::to_string(resolution) +
                                              "²: acne (false shadow) solid, false light dashed");
    chart.y_title = "% of receiver pixels";
    return chart;
}

}  // namespace

PlotPanel::PlotPanel(QWidget* parent) : QWidget(parent), kind_(new QComboBox(this)), image_(new QLabel(this)) {
    kind_->setObjectName("plotKind");
    kind_->addItem("Error against map resolution", static_cast<int>(Kind::error_against_resolution));
    kind_->addItem(QString("Shimmer: the camera moving sideways, %1 frames").arg(kShimmerFrames),
                   static_cast<int>(Kind::shimmer));
    kind_->addItem("Acne / peter panning against bias_slope", static_cast<int>(Kind::acne_against_bias));
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
    const QString name = QString::fromStdString(method);
    switch (kind()) {
        case Kind::shimmer:
            return QString("plot: %1 along %2 frames of a sideways camera path").arg(name).arg(kShimmerFrames);
        case Kind::acne_against_bias:
            return QString(
                       "plot: measuring %1 at 0 and 1/16 to 32 times the slope-scaled bias against the exact "
                       "reference")
                .arg(name);
        case Kind::error_against_resolution: break;
    }
    return QString("plot: measuring %1 at 256² to 2048² against the exact reference").arg(name);
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
    } else if (kind() == Kind::acne_against_bias) {
        chart = acne_against_bias(context, *method, overrides, resolution);
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
