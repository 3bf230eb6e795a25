#include "gui/plot_panel.hpp"

#include <QComboBox>
#include <QDir>
#include <QLabel>
#include <QPixmap>
#include <QVBoxLayout>

namespace shadowlab {

PlotPanel::PlotPanel(QWidget* parent) : QWidget(parent), kind_(new QComboBox(this)), image_(new QLabel(this)) {
    kind_->setObjectName("plotKind");
    kind_->addItem("Error against map resolution", static_cast<int>(Kind::error_against_resolution));
    kind_->addItem(QString("Shimmer: the camera moving sideways, %1 frames").arg(kShimmerFrames),
                   static_cast<int>(Kind::shimmer));
    kind_->addItem("Acne / peter panning against bias_slope", static_cast<int>(Kind::acne_against_bias));
    kind_->addItem("Texels per unit of view depth against the ideal", static_cast<int>(Kind::density_along_view));
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

PlotRequest PlotPanel::request(const Scene& scene, const std::string& method,
                               const std::map<std::string, std::string>& settings, int resolution) const {
    return {.kind = kind(), .scene = scene, .method = method, .settings = settings, .resolution = resolution};
}

void PlotPanel::show_plot(const Plot& plot) {
    shimmer_ = plot.shimmer;
    const QString file = QDir::temp().filePath("shadowlab-plot.png");
    write_chart_png(plot.chart, file.toStdString());
    image_->setPixmap(QPixmap(file));
}

}  // namespace shadowlab
