#pragma once
// The plot panel: for the current method, measured on the exact reference of a small camera image
// and drawn with VTK's charts, either its error and aliasing against map resolution, its shimmer
// while the camera moves sideways (the same measure as `shadowlab shimmer`), or its acne and peter
// panning against the slope-scaled bias's scale (as `shadowlab sweep --bias` draws them).
#include <optional>
#include <QWidget>

#include "metrics/shimmer.hpp"
#include "scene/scene.hpp"

class QComboBox;
class QLabel;

namespace shadowlab {

class PlotPanel : public QWidget {
    Q_OBJECT
public:
    enum class Kind { error_against_resolution, shimmer, acne_against_bias };
    // The shimmer plot's path and image: `shadowlab shimmer SCENE --frames 30 --size 320x320` measures the same.
    static constexpr int kShimmerFrames = 30, kImageWidth = 320;

    explicit PlotPanel(QWidget* parent = nullptr);
    Kind kind() const;
    void set_kind(Kind kind);
    // What update_plot will measure, for the window's progress line.
    QString work(const std::string& method) const;
    // Measures `method` (at 256² to 2048², or along the path or at each bias_slope at `resolution`)
    // and shows the plot; returns false for a method without a map.
    bool update_plot(const Scene& scene, const std::string& method, const std::map<std::string, std::string>& settings,
                     int resolution);
    const std::optional<Shimmer>& last_shimmer() const { return shimmer_; }

signals:
    void kindChosen();

private:
    QComboBox* kind_;
    QLabel* image_;
    std::optional<Shimmer> shimmer_;
};

}  // namespace shadowlab
