#pragma once
// The Plot dock: one of three plots of the current method (gui/plot_measure.hpp), chosen here,
// measured by the window's worker off the GUI thread and drawn here with VTK's charts.
#include <map>
#include <optional>
#include <string>
#include <QWidget>

#include "gui/plot_measure.hpp"

class QComboBox;
class QLabel;

namespace shadowlab {

class PlotPanel : public QWidget {
    Q_OBJECT
public:
    using Kind = PlotKind;

    explicit PlotPanel(QWidget* parent = nullptr);
    Kind kind() const;
    void set_kind(Kind kind);
    // The plot chosen, of `method` on `scene` (at 256² to 2048², or along the path or at each
    // bias_slope at `resolution`): for measure_plot.
    PlotRequest request(const Scene& scene, const std::string& method,
                        const std::map<std::string, std::string>& settings, int resolution) const;
    void show_plot(const Plot& plot);
    const std::optional<Shimmer>& last_shimmer() const { return shimmer_; }

signals:
    void kindChosen();

private:
    QComboBox* kind_;
    QLabel* image_;
    std::optional<Shimmer> shimmer_;
};

}  // namespace shadowlab
