#pragma once
// The controls: method (the map methods, then the geometric techniques), its settings (each within
// its declared range; a map method's own first, then its lookup's under a Filter header, only those
// the chosen filter reads, and a Depth bias header), map resolution, depth bias, the camera's aspect
// (the scene's, locked, or the Camera panel's), the light's direction as azimuth and elevation, for
// shadow volumes a toggle that moves the camera into a shadow, and a toggle that shows the Camera
// view's shadows alone.
#include <utility>
#include <vector>
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

    // Method, settings (the filter settings the chosen filter does not read left out: their defaults
    // apply), resolution, bias.
    InspectionRequest request() const;
    glm::dvec3 light_direction() const;
    void set_light_direction(const glm::dvec3& direction);  // without emitting changed()
    void set_method(const QString& name);
    // A text setting of the current method (a file path: custom's `matrices`); emits changed().
    // False when the method has no such text setting.
    bool set_text_setting(const QString& name, const QString& value);
    void set_resolution(int resolution);
    // Another run in one change (the Diagnosis dock's remedy): the method, each of its settings the
    // request names, the resolution (offered if it was not) and the bias; the light, the aspect and
    // the toggles stay. Emits changed() once.
    void set_request(const InspectionRequest& request);
    QComboBox* method_selector() const { return method_; }
    bool camera_in_shadow() const;
    bool aspect_locked() const;     // the scene camera's aspect, as the CLI computes; else the Camera panel's
    bool shadow_only() const;       // the Camera view as a lit mask: white lit, black shadowed
    void clear_camera_in_shadow();  // without emitting cameraInShadowToggled()
    // A second configuration's panel (the window's compare mode): the run alone, method, settings,
    // resolution and bias; the light, the aspect and the toggles are the first panel's.
    void show_the_run_only();

signals:
    void changed();       // any setting
    void lightChanged();  // the direction widget
    void cameraInShadowToggled(bool inside);
    void aspectChanged();
    void shadowOnlyToggled();

private:
    void rebuild_settings();
    QWidget* connected_editor(const SettingSpec& spec, QWidget* parent);
    void show_filter_settings();                // the Filter group's rows the chosen filter reads
    bool applies(const QWidget* editor) const;  // is the editor's setting read under the chosen filter?

    QComboBox* method_;
    QWidget* settings_box_;
    QWidget* settings_content_ = nullptr;   // the method's settings, rebuilt per method
    QFormLayout* settings_form_ = nullptr;  // its own, then under the Filter and Depth bias headers
    QLabel* filter_header_ = nullptr;       // the Filter group's first row; none for a geometric technique
    std::vector<std::pair<QLabel*, QWidget*>> filter_rows_;  // the Filter group's, shown or not
    QComboBox* filter_ = nullptr;                            // the lookup's filter; none for a technique
    std::vector<QWidget*> setting_editors_;                  // every setting's, named by the setting
    QComboBox* resolution_;
    QDoubleSpinBox* bias_;
    QSlider* azimuth_;
    QSlider* elevation_;
    QLabel* light_label_;
    QCheckBox* camera_in_shadow_;
    QComboBox* aspect_;
    QCheckBox* shadow_only_;
    QFormLayout* general_ = nullptr;  // method, map, bias, aspect and the toggles
    QWidget* light_box_ = nullptr;
};

}  // namespace shadowlab
