#pragma once
// The plot panel: the current method's error and aliasing against map resolution, measured on the
// exact reference (a small camera image) and drawn with VTK's charts.
#include <QWidget>

#include "scene/scene.hpp"

class QLabel;

namespace shadowlab {

class PlotPanel : public QWidget {
    Q_OBJECT
public:
    explicit PlotPanel(QWidget* parent = nullptr);
    // Measures `method` at 256² to 2048² and shows the plot; returns false (and says why) on failure.
    bool update_plot(const Scene& scene, const std::string& method, const std::map<std::string, std::string>& settings);

private:
    QLabel* image_;
};

}  // namespace shadowlab
