#include "gui/controls_panel.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

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

#include "lookup/lookup_settings.hpp"
#include "scene/light.hpp"

namespace shadowlab {
namespace {

QSlider* slider(int min, int max, QWidget* parent) {
    auto* s = new QSlider(Qt::Horizontal, parent);
    s->setRange(min, max);
    return s;
}

// A setting's editor: a spin box over its range, a combo box over its choices, or a line of
// comma-separated numbers for a list or of free text (a file's path).
QWidget* setting_editor(const SettingSpec& spec, QWidget* parent) {
    if (spec.is_list || spec.is_text) return new QLineEdit(QString::fromStdString(spec.default_value), parent);
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

// Where the form lists a setting: among the method's own, or in the lookup's Filter group or the
// group every filter reads (the depth biases, the depth format and contact shadows).
enum class SettingGroup { own, filter, bias };

SettingGroup group_of(const std::string& name) {
    if (!is_lookup_setting(name)) return SettingGroup::own;
    return filters_reading(name).empty() ? SettingGroup::bias : SettingGroup::filter;
}

QLabel* group_header(SettingGroup group, QWidget* parent) {
    auto* header =
        new QLabel(group == SettingGroup::filter ? "Filter" : "Depth bias, format and contact shadows", parent);
    header->setObjectName(group == SettingGroup::filter ? "filterSettings" : "biasSettings");
    QFont bold = header->font();
    bold.setBold(true);
    header->setFont(bold);
    return header;
}

QString setting_text(const QWidget* editor) {
    if (auto* box = qobject_cast<const QComboBox*>(editor)) return box->currentText();
    if (auto* line = qobject_cast<const QLineEdit*>(editor)) return line->text();
    return QString::number(static_cast<const QDoubleSpinBox*>(editor)->value(), 'g', 12);
}

// The editor shows `text`, without telling anyone.
void set_setting_text(QWidget* editor, const QString& text) {
    const QSignalBlocker block(editor);
    if (auto* box = qobject_cast<QComboBox*>(editor))
        box->setCurrentText(text);
    else if (auto* line = qobject_cast<QLineEdit*>(editor))
        line->setText(text);
    else
        static_cast<QDoubleSpinBox*>(editor)->setValue(text.toDouble());
}

}  // namespace

ControlsPanel::ControlsPanel(QWidget* parent)
    : QWidget(parent),
      method_(new QComboBox(this)),
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
    camera_in_shadow_->setToolTip(
        "move the camera into a caster's shadow volume: z-pass counts go wrong there, z-fail holds");
    aspect_->setObjectName("aspect");
    aspect_->addItem("scene (locked)", true);
    aspect_->addItem("Camera panel", false);
    aspect_->setToolTip(
        "the camera's aspect the method computes with: the scene's, as `shadowlab inspect` does (the "
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
    bias_->setToolTip(
        "depth bias in world units along the light; 'slope-scaled' = the texel's world size times 1 + tan θ, per "
        "pixel");
    azimuth_->setToolTip("light azimuth (degrees about +y)");
    elevation_->setToolTip("light elevation (degrees above the horizon)");
    new QVBoxLayout(settings_box_);

    auto* general = new QFormLayout;
    general_ = general;
    general->addRow("Method", method_);
    general->addRow("Map", resolution_);
    general->addRow("Bias", bias_);
    general->addRow("Aspect", aspect_);
    general->addRow(camera_in_shadow_);
    general->addRow(shadow_only_);
    auto* light = new QGroupBox("Light direction", this);
    light_box_ = light;
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
    for (QSlider* s : {azimuth_, elevation_})
        connect(s, &QSlider::valueChanged, this, [this] {
            const glm::dvec3 d = light_direction();
            light_label_->setText(QString("(%1, %2, %3)").arg(d.x, 0, 'f', 3).arg(d.y, 0, 'f', 3).arg(d.z, 0, 'f', 3));
            emit lightChanged();
        });
}

void ControlsPanel::show_the_run_only() {
    for (QWidget* shared : {general_->labelForField(aspect_), static_cast<QWidget*>(aspect_),
                            static_cast<QWidget*>(camera_in_shadow_), static_cast<QWidget*>(shadow_only_), light_box_})
        shared->hide();
}

// The method's own settings, then its lookup's under two headers in the same form (its labels in
// one column): the filter with the settings it reads (the others taken out, kept for when their
// filter is chosen again) and the depth bias. The registry appends the lookup's settings, filter
// first, so each group's rows follow one another.
void ControlsPanel::rebuild_settings() {
    delete settings_content_;
    setting_editors_.clear();
    filter_rows_.clear();
    filter_ = nullptr;
    filter_header_ = nullptr;
    const Method& method = method_or_throw(method_->currentData().toString().toStdString());
    resolution_->setEnabled(method.makes_maps());  // a geometric technique has no map
    bias_->setEnabled(method.makes_maps());
    settings_content_ = new QWidget(settings_box_);
    settings_box_->layout()->addWidget(settings_content_);
    settings_form_ = new QFormLayout(settings_content_);
    settings_form_->setContentsMargins(0, 0, 0, 0);
    SettingGroup group = SettingGroup::own;
    for (const SettingSpec& spec : method.settings) {
        if (group_of(spec.name) != group) {
            group = group_of(spec.name);
            QLabel* header = group_header(group, settings_content_);
            settings_form_->addRow(header);
            if (group == SettingGroup::filter) filter_header_ = header;
        }
        QWidget* editor = connected_editor(spec, settings_content_);
        auto* label = new QLabel(QString::fromStdString(spec.name), settings_content_);
        settings_form_->addRow(label, editor);
        if (group == SettingGroup::filter) filter_rows_.emplace_back(label, editor);
        setting_editors_.push_back(editor);
    }
    settings_box_->setVisible(!method.settings.empty());
    show_filter_settings();
}

// A setting's editor, named by the setting, emitting changed() when edited; the filter's chooser
// also shows the settings it reads.
QWidget* ControlsPanel::connected_editor(const SettingSpec& spec, QWidget* parent) {
    QWidget* editor = setting_editor(spec, parent);
    editor->setObjectName(QString::fromStdString(spec.name));
    editor->setToolTip(QString::fromStdString(spec.description));
    if (auto* box = qobject_cast<QComboBox*>(editor)) {
        if (spec.name == "filter") {
            filter_ = box;
            connect(box, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
                    &ControlsPanel::show_filter_settings);
        }
        connect(box, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &ControlsPanel::changed);
    } else if (auto* line = qobject_cast<QLineEdit*>(editor)) {
        connect(line, &QLineEdit::editingFinished, this, &ControlsPanel::changed);
    } else {
        connect(static_cast<QDoubleSpinBox*>(editor), &QDoubleSpinBox::editingFinished, this, &ControlsPanel::changed);
    }
    return editor;
}

bool ControlsPanel::applies(const QWidget* editor) const {
    const std::vector<std::string>& read_by = filters_reading(editor->objectName().toStdString());
    if (!filter_ || read_by.empty()) return true;  // a method's own, or the bias's
    return std::find(read_by.begin(), read_by.end(), filter_->currentText().toStdString()) != read_by.end();
}

// The rows are taken out and the shown ones put back under the Filter header: a hidden row of a
// QFormLayout (Qt 5) would still take its spacing.
void ControlsPanel::show_filter_settings() {
    if (!filter_header_) return;
    for (const auto& [label, editor] : filter_rows_) {
        if (settings_form_->indexOf(editor) < 0) continue;                       // a row taken out before
        const QFormLayout::TakeRowResult row = settings_form_->takeRow(editor);  // the widgets stay, the items are ours
        delete row.labelItem;
        delete row.fieldItem;
    }
    int row = 0;
    QFormLayout::ItemRole role;
    settings_form_->getWidgetPosition(filter_header_, &row, &role);
    for (const auto& [label, editor] : filter_rows_) {
        const bool shown = applies(editor);
        label->setVisible(shown);
        editor->setVisible(shown);
        if (shown) settings_form_->insertRow(++row, label, editor);
    }
}

InspectionRequest ControlsPanel::request() const {
    InspectionRequest r;
    r.method = method_->currentData().toString().toStdString();
    r.resolution = resolution_->currentData().toInt();
    r.bias = bias_->value() <= bias_->minimum() ? -1.0 : bias_->value();
    for (const QWidget* editor : setting_editors_)
        if (applies(editor)) r.settings[editor->objectName().toStdString()] = setting_text(editor).toStdString();
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
    light_label_->setText(
        QString("(%1, %2, %3)").arg(direction.x, 0, 'f', 3).arg(direction.y, 0, 'f', 3).arg(direction.z, 0, 'f', 3));
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

bool ControlsPanel::set_text_setting(const QString& name, const QString& value) {
    for (QWidget* editor : setting_editors_)
        if (auto* line = qobject_cast<QLineEdit*>(editor); line && editor->objectName() == name) {
            line->setText(value);
            emit changed();
            return true;
        }
    return false;
}

void ControlsPanel::set_resolution(int resolution) {
    const int index = resolution_->findData(resolution);
    if (index >= 0) resolution_->setCurrentIndex(index);
}

void ControlsPanel::set_request(const InspectionRequest& request) {
    if (method_->currentData().toString().toStdString() != request.method) {
        const QSignalBlocker block(method_);
        set_method(QString::fromStdString(request.method));
        rebuild_settings();
    }
    for (QWidget* editor : setting_editors_)
        if (const auto it = request.settings.find(editor->objectName().toStdString()); it != request.settings.end())
            set_setting_text(editor, QString::fromStdString(it->second));
    show_filter_settings();
    if (request.resolution > 0) {
        const QSignalBlocker block(resolution_);
        if (resolution_->findData(request.resolution) < 0) {  // in order among the others
            int at = 0;
            while (at < resolution_->count() && resolution_->itemData(at).toInt() < request.resolution) ++at;
            resolution_->insertItem(at, QString::number(request.resolution) + "²", request.resolution);
        }
        set_resolution(request.resolution);
    }
    bias_->setValue(request.bias < 0.0 ? bias_->minimum() : request.bias);  // tells no one: editingFinished
    emit changed();
}

}  // namespace shadowlab
