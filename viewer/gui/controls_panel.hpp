#pragma once
// The controls: method (the map methods, then the geometric techniques), its settings (each within
// its declared range), map resolution, depth bias, the camera's aspect (the scene's, locked, or the
// Camera panel's), the light's direction as azimuth and elevation, for shadow volumes a toggle that
// moves the camera into a shadow, and a toggle that shows the Camera view's shadows alone.
#include <QWidget>
#include <glm/glm.hpp>

#include "model/inspection.hpp"

class QCheckBox;
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
    bool camera_in_shadow() const;
    bool aspect_locked() const;  // the scene camera's aspect, as the CLI computes; else the Camera panel's
    bool shadow_only() const;    // the Camera view as a lit mask: white lit, black shadowed
    void clear_camera_in_shadow();  // without emitting cameraInShadowToggled()

signals:
    void changed();       // any setting
    void lightChanged();  // the direction widget
    void cameraInShadowToggled(bool inside);
    void aspectChanged();
    void shadowOnlyToggled();

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
    QCheckBox* camera_in_shadow_;
    QComboBox* aspect_;
    QCheckBox* shadow_only_;
};

}  // namespace shadowlab
