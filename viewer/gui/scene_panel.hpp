#pragma once
// The scene's parts: its objects, each with whether it casts shadows and whether it receives them
// (is judged as a receiver), and for a glTF scene which of the file's cameras and lights it takes.
// The panel only shows and asks: the window changes the scene on its signals (and saves the choices
// and roles with save_scene_referencing_gltf).
#include <QWidget>

#include "scene/gltf_scene.hpp"
#include "scene/scene.hpp"
#include "scene/scene_choice.hpp"

class QComboBox;
class QTableWidget;
class QTableWidgetItem;

namespace shadowlab {

class ScenePanel : public QWidget {
    Q_OBJECT
public:
    explicit ScenePanel(QWidget* parent = nullptr);

    // Lists the scene's objects and their roles. `gltf`: the cameras and lights of the glTF file the
    // scene came from, `choice` the ones it took; nullptr for a scene of its own (no choice shown).
    // Emits nothing.
    void set_scene(const Scene& scene, const GltfContents* gltf = nullptr, const SceneChoice& choice = {});

signals:
    void rolesChanged(int object, bool casts, bool receives);  // the object's index in Scene::objects
    void cameraChosen(int index);                              // of the glTF file's cameras
    void lightChosen(int index);                               // of its KHR_lights_punctual lights

private:
    void role_toggled(QTableWidgetItem* item);
    bool checked(int row, int column) const;

    QTableWidget* objects_;
    QWidget* choices_;  // the camera and light selectors, shown for a glTF scene
    QComboBox* camera_;
    QComboBox* light_;
};

}  // namespace shadowlab
