#include "gui/plot_panel.hpp"

#include <QDir>
#include <QLabel>
#include <QPixmap>
#include <QVBoxLayout>

#include "metrics/measurement.hpp"
#include "plot/chart_png.hpp"

namespace shadowlab {

PlotPanel::PlotPanel(QWidget* parent) : QWidget(parent), image_(new QLabel(this)) {
    image_->setAlignment(Qt::AlignCenter);
    image_->setMinimumSize(320, 200);
    image_->setScaledContents(false);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(image_);
}

bool PlotPanel::update_plot(const Scene& scene, const std::string& method_name,
                            const std::map<std::string, std::string>& overrides) {
    const Method* method = find_method(method_name);
    if (!method || !method->makes_maps()) return false;
    const MeasureContext context = prepare_measurement(scene, 320, static_cast<int>(320 / scene.camera.aspect));
    const Settings settings = resolve_settings(method->name, method->settings, overrides);
    ChartSpec chart;
    chart.title = method_name + ": error against map resolution";
    chart.x_title = "map resolution (texels per side)";
    chart.y_title = "misclassified % / max perspective m (px)";
    chart.log_x = chart.log_y = true;
    chart.width = 520;
    chart.height = 320;
    ChartSeries wrong{"misclassified %", {}, {}, {}, true, {}, {}};
    // The perspective factor of m: the part a parameterization (and its resolution) controls; m's
    // own max is set by faces edge-on to the light, whatever the map.
    ChartSeries m{"max perspective m (texel width in pixels)", {}, {}, {}, true, {}, {}};
    for (int resolution : {256, 512, 1024, 2048}) {
        const Measurement r = measure(context, *method, settings, resolution, -1.0);
        wrong.x.push_back(resolution), wrong.y.push_back(std::max(1e-3, 100.0 * r.error.misclassified));
        m.x.push_back(resolution), m.y.push_back(std::max(1e-3, r.error.m_perspective.max));
    }
    chart.series = {wrong, m};
    const QString file = QDir::temp().filePath("shadowlab-plot.png");
    write_chart_png(chart, file.toStdString());
    image_->setPixmap(QPixmap(file));
    return true;
}

}  // namespace shadowlab
