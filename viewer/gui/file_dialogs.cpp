#include "gui/file_dialogs.hpp"

#include <QFileDialog>

namespace shadowlab {

QString ask_scene_to_open(QWidget* parent) {
    return QFileDialog::getOpenFileName(parent, "Open a scene or a mesh", QString(),
                                        "Scenes and meshes (*.json *.obj *.ply *.stl *.gltf *.glb);;All files (*)");
}

QString ask_light_matrices_to_import(QWidget* parent) {
    return QFileDialog::getOpenFileName(parent, "Import an engine's light matrices", QString(),
                                        "Light matrices (*.glsl *.hlsl *.json *.txt);;All files (*)");
}

QString ask_png_to_export(QWidget* parent, const QString& name) {
    return QFileDialog::getSaveFileName(parent, "Export view", name, "PNG images (*.png)");
}

QString ask_matrices_to_export(QWidget* parent, MatrixFormat format) {
    const char* suffix = format == MatrixFormat::glsl ? "glsl" : format == MatrixFormat::hlsl ? "hlsl" : "json";
    return QFileDialog::getSaveFileName(parent, "Export matrices", QString("shadow_map.") + suffix);
}

QString ask_scene_to_save(QWidget* parent, const QString& name) {
    return QFileDialog::getSaveFileName(parent, "Save the scene (a JSON referencing its glTF file)", name + ".json",
                                        "Scenes (*.json)");
}

}  // namespace shadowlab
