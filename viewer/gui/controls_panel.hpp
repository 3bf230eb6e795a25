#pragma once
// The controls: method, its settings (each within its declared range), map resolution, depth
// bias, and the light's direction as azimuth and elevation.
#include <QWidget>
#include <glm/glm.hpp>

#include "model/inspection.hpp"

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QSlider;
class QLabel;

namespace shadowlab {

class ControlsPanel : public QWidget {
    Q_OBJECT
public:
    explicit ControlsPanel(QWidget* parent = nullptr);

    InspectionRequest request() const;  // method, settings, resolution, bias
    glm::dvec3 light_direction() const;
    void set_light_direction(const glm::dvec3& direction);  // without emitting changed()
    void set_method(const QString& name);
    void set_resolution(int resolution);
    QComboBox* method_selector() const { return method_; }

signals:
    void changed();       // any setting
    void lightChanged();  // the direction widget

private:
    void rebuild_settings();

    QComboBox* method_;
    QFormLayout* settings_form_;
    QWidget* settings_box_;
    QComboBox* resolution_;
    QDoubleSpinBox* bias_;
    QSlider* azimuth_;
    QSlider* elevation_;
    QLabel* light_label_;
};

}  // namespace shadowlab
