#include "gui/scene_panel.hpp"

#include <QComboBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

namespace shadowlab {
namespace {

enum Column { kName, kCasts, kReceives, kColumns };

QTableWidgetItem* role_item(bool on) {
    auto* item = new QTableWidgetItem;
    item->setFlags(Qt::ItemIsUserCheckable | Qt::ItemIsEnabled);
    item->setCheckState(on ? Qt::Checked : Qt::Unchecked);
    return item;
}

// "1: side camera (perspective)", or "1 (perspective)" for an item without a name.
QString item_label(std::size_t index, const GltfItem& item) {
    const QString name = item.name.empty() ? "" : ": " + QString::fromStdString(item.name);
    return QString::number(index) + name + " (" + QString::fromStdString(item.type) + ")";
}

// The file's items, the chosen one current; a file without any gets ShadowLab's default, the one choice.
void fill(QComboBox* combo, const std::vector<GltfItem>& items, std::size_t chosen, const QString& fallback) {
    const QSignalBlocker quiet(combo);
    combo->clear();
    for (std::size_t i = 0; i < items.size(); ++i) combo->addItem(item_label(i, items[i]));
    if (items.empty()) combo->addItem(fallback);
    combo->setEnabled(items.size() > 1);
    combo->setCurrentIndex(int(chosen));
}

}  // namespace

ScenePanel::ScenePanel(QWidget* parent)
    : QWidget(parent),
      objects_(new QTableWidget(0, kColumns, this)),
      choices_(new QWidget(this)),
      camera_(new QComboBox(choices_)),
      light_(new QComboBox(choices_)) {
    objects_->setObjectName("objects");
    objects_->setHorizontalHeaderLabels({"object", "casts", "receives"});
    objects_->horizontalHeader()->setSectionResizeMode(kName, QHeaderView::Stretch);
    objects_->horizontalHeader()->setSectionResizeMode(kCasts, QHeaderView::ResizeToContents);
    objects_->horizontalHeader()->setSectionResizeMode(kReceives, QHeaderView::ResizeToContents);
    objects_->verticalHeader()->hide();
    objects_->setSelectionMode(QAbstractItemView::NoSelection);
    objects_->setToolTip("casts: draws into the shadow maps; receives: its shadows are judged against the reference");
    camera_->setObjectName("camera");
    light_->setObjectName("light");

    auto* form = new QFormLayout(choices_);
    form->setContentsMargins(0, 0, 0, 0);
    form->addRow("Camera", camera_);
    form->addRow("Light", light_);
    choices_->hide();
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(choices_);
    layout->addWidget(objects_);

    connect(objects_, &QTableWidget::itemChanged, this, &ScenePanel::role_toggled);
    connect(camera_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &ScenePanel::cameraChosen);
    connect(light_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &ScenePanel::lightChosen);
}

void ScenePanel::set_scene(const Scene& scene, const GltfContents* gltf, const SceneChoice& choice) {
    {
        const QSignalBlocker quiet(objects_);
        objects_->setRowCount(int(scene.objects.size()));
        for (int row = 0; row < objects_->rowCount(); ++row) {
            const SceneObject& object = scene.objects[std::size_t(row)];
            auto* name = new QTableWidgetItem(QString::fromStdString(object.name));
            name->setFlags(Qt::ItemIsEnabled);
            objects_->setItem(row, kName, name);
            objects_->setItem(row, kCasts, role_item(object.casts));
            objects_->setItem(row, kReceives, role_item(object.receives));
        }
    }
    choices_->setVisible(gltf != nullptr);
    if (!gltf) return;
    fill(camera_, gltf->cameras, choice.camera, "the default camera (the file has none)");
    fill(light_, gltf->lights, choice.light, "the default sun (the file has none)");
}

void ScenePanel::role_toggled(QTableWidgetItem* item) {
    if (item->column() == kName) return;
    emit rolesChanged(item->row(), checked(item->row(), kCasts), checked(item->row(), kReceives));
}

bool ScenePanel::checked(int row, int column) const { return objects_->item(row, column)->checkState() == Qt::Checked; }

}  // namespace shadowlab
