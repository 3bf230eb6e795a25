#include "gui/controls_panel.hpp"

#include <cmath>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

#include "scene/light.hpp"

namespace shadowlab {
namespace {

QSlider* slider(int min, int max, QWidget* parent) {
    auto* s = new QSlider(Qt::Horizontal, parent);
    s->setRange(min, max);
    return s;
}

// A setting's editor: a spin box over its range, a combo box over its choices, or a line of
// comma-separated numbers for a list.
QWidget* setting_editor(const SettingSpec& spec, QWidget* parent) {
    if (spec.is_list) return new QLineEdit(QString::fromStdString(spec.default_value), parent);
    if (spec.is_choice()) {
        auto* box = new QComboBox(parent);
        for (const std::string& choice : spec.choices) box->addItem(QString::fromStdString(choice));
        box->setCurrentText(QString::fromStdString(spec.default_value));
        return box;
    }
    auto* spin = new QDoubleSpinBox(parent);
    spin->setDecimals(4);
    spin->setRange(spec.min, std::min(spec.max, 1e9));
    spin->setSingleStep(std::max((std::min(spec.max, 1e3) - spec.min) / 100.0, 1e-4));
    spin->setValue(std::stod(spec.default_value));
    return spin;
}

}  // namespace

ControlsPanel::ControlsPanel(QWidget* parent)
    : QWidget(parent),
      method_(new QComboBox(this)),
      settings_form_(nullptr),
      settings_box_(new QGroupBox("Method settings", this)),
      resolution_(new QComboBox(this)),
      bias_(new QDoubleSpinBox(this)),
      azimuth_(slider(0, 359, this)),
      elevation_(slider(1, 90, this)),
      light_label_(new QLabel(this)),
      camera_in_shadow_(new QCheckBox("Camera in shadow", this)),
      aspect_(new QComboBox(this)),
      shadow_only_(new QCheckBox("Shadow only", this)) {
    method_->setObjectName("methodSelector");
    // The registry's order: the maps, a separator, the geometric techniques.
    for (const Method& m : all_methods()) {
        if (method_->count() > 0 && !m.makes_maps() && all_methods()[method_->count() - 1].makes_maps())
            method_->insertSeparator(method_->count());
        method_->addItem(QString::fromStdString(m.name), QString::fromStdString(m.name));
        method_->setItemData(method_->count() - 1,
                             QString::fromStdString(m.title + ": " + m.description + " (" + to_string(m.produces()) +
                                                    "; lights: " + m.lights.text() + ")"),
                             Qt::ToolTipRole);
    }
    camera_in_shadow_->setObjectName("cameraInShadow");
    camera_in_shadow_->setToolTip("move the camera into a caster's shadow volume: z-pass counts go wrong there, z-fail holds");
    aspect_->setObjectName("aspect");
    aspect_->addItem("scene (locked)", true);
    aspect_->addItem("Camera panel", false);
    aspect_->setToolTip("the camera's aspect the method computes with: the scene's, as `shadowlab inspect` does (the "
                        "Camera panel letterboxes), or the Camera panel's shape");
    shadow_only_->setObjectName("shadowOnly");
    shadow_only_->setToolTip("the Camera view's shadows alone: white where lit, black where shadowed");
    method_->setCurrentText("focused");
    for (int r : {128, 256, 512, 1024, 2048, 4096}) resolution_->addItem(QString::number(r) + "²", r);
    resolution_->setCurrentIndex(3);
    bias_->setRange(-0.0001, 1e4);
    bias_->setDecimals(4);
    bias_->setSingleStep(0.005);
    bias_->setSpecialValueText("slope-scaled");  // the minimum: per pixel, as the metrics use
    bias_->setValue(bias_->minimum());
    bias_->setToolTip("depth bias in world units along the light; 'slope-scaled' = the texel's world size times 1 + tan θ, per pixel");
    azimuth_->setToolTip("light azimuth (degrees about +y)");
    elevation_->setToolTip("light elevation (degrees above the horizon)");
    settings_form_ = new QFormLayout(settings_box_);

    auto* general = new QFormLayout;
    general->addRow("Method", method_);
    general->addRow("Map", resolution_);
    general->addRow("Bias", bias_);
    general->addRow("Aspect", aspect_);
    general->addRow(camera_in_shadow_);
    general->addRow(shadow_only_);
    auto* light = new QGroupBox("Light direction", this);
    auto* light_form = new QFormLayout(light);
    light_form->addRow("Azimuth", azimuth_);
    light_form->addRow("Elevation", elevation_);
    light_form->addRow(light_label_);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(general);
    layout->addWidget(settings_box_);
    layout->addWidget(light);
    layout->addStretch(1);
    rebuild_settings();

    connect(method_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] {
        rebuild_settings();
        emit changed();
    });
    connect(resolution_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &ControlsPanel::changed);
    connect(camera_in_shadow_, &QCheckBox::toggled, this, &ControlsPanel::cameraInShadowToggled);
    connect(aspect_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &ControlsPanel::aspectChanged);
    connect(shadow_only_, &QCheckBox::toggled, this, &ControlsPanel::shadowOnlyToggled);
    connect(bias_, &QDoubleSpinBox::editingFinished, this, &ControlsPanel::changed);
    for (QSlider* s : {azimuth_, elevation_}) connect(s, &QSlider::valueChanged, this, [this] {
        const glm::dvec3 d = light_direction();
        light_label_->setText(QString("(%1, %2, %3)").arg(d.x, 0, 'f', 3).arg(d.y, 0, 'f', 3).arg(d.z, 0, 'f', 3));
        emit lightChanged();
    });
}

void ControlsPanel::rebuild_settings() {
    while (settings_form_->rowCount() > 0) settings_form_->removeRow(0);
    const Method& method = method_or_throw(method_->currentData().toString().toStdString());
    resolution_->setEnabled(method.makes_maps());  // a geometric technique has no map
    bias_->setEnabled(method.makes_maps());
    for (const SettingSpec& spec : method.settings) {
        QWidget* editor = setting_editor(spec, settings_box_);
        editor->setObjectName(QString::fromStdString(spec.name));
        editor->setToolTip(QString::fromStdString(spec.description));
        if (auto* box = qobject_cast<QComboBox*>(editor))
            connect(box, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &ControlsPanel::changed);
        else if (auto* line = qobject_cast<QLineEdit*>(editor))
            connect(line, &QLineEdit::editingFinished, this, &ControlsPanel::changed);
        else
            connect(static_cast<QDoubleSpinBox*>(editor), &QDoubleSpinBox::editingFinished, this, &ControlsPanel::changed);
        settings_form_->addRow(QString::fromStdString(spec.name), editor);
    }
    settings_box_->setVisible(!method.settings.empty());
}

InspectionRequest ControlsPanel::request() const {
    InspectionRequest r;
    r.method = method_->currentData().toString().toStdString();
    r.resolution = resolution_->currentData().toInt();
    r.bias = bias_->value() <= bias_->minimum() ? -1.0 : bias_->value();
    for (int row = 0; row < settings_form_->rowCount(); ++row) {
        QWidget* editor = settings_form_->itemAt(row, QFormLayout::FieldRole)->widget();
        const std::string key = editor->objectName().toStdString();
        if (auto* box = qobject_cast<QComboBox*>(editor))
            r.settings[key] = box->currentText().toStdString();
        else if (auto* line = qobject_cast<QLineEdit*>(editor))
            r.settings[key] = line->text().toStdString();
        else
            r.settings[key] = QString::number(static_cast<QDoubleSpinBox*>(editor)->value(), 'g', 12).toStdString();
    }
    return r;
}

glm::dvec3 ControlsPanel::light_direction() const {
    return light_direction_from_angles(azimuth_->value(), elevation_->value());
}

void ControlsPanel::set_light_direction(const glm::dvec3& direction) {
    const LightAngles angles = light_angles(direction);
    const QSignalBlocker block_a(azimuth_), block_e(elevation_);
    elevation_->setValue(static_cast<int>(std::lround(angles.elevation_deg)));
    azimuth_->setValue(static_cast<int>(std::lround(angles.azimuth_deg)) % 360);
    light_label_->setText(QString("(%1, %2, %3)").arg(direction.x, 0, 'f', 3).arg(direction.y, 0, 'f', 3).arg(direction.z, 0, 'f', 3));
}

bool ControlsPanel::camera_in_shadow() const { return camera_in_shadow_->isChecked(); }

bool ControlsPanel::aspect_locked() const { return aspect_->currentData().toBool(); }

bool ControlsPanel::shadow_only() const { return shadow_only_->isChecked(); }

void ControlsPanel::clear_camera_in_shadow() {
    const QSignalBlocker block(camera_in_shadow_);
    camera_in_shadow_->setChecked(false);
}

void ControlsPanel::set_method(const QString& name) {
    const int index = method_->findData(name);
    if (index >= 0) method_->setCurrentIndex(index);
}

void ControlsPanel::set_resolution(int resolution) {
    const int index = resolution_->findData(resolution);
    if (index >= 0) resolution_->setCurrentIndex(index);
}

}  // namespace shadowlab
