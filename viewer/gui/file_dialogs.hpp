#pragma once
// The window's file dialogs, each asking for one path: empty when the user cancels.
#include <QString>

#include "exchange/matrix_export.hpp"

class QWidget;

namespace shadowlab {

QString ask_scene_to_open(QWidget* parent);                            // a scene JSON, a glTF scene or a mesh
QString ask_light_matrices_to_import(QWidget* parent);                 // an engine's light matrices
QString ask_png_to_export(QWidget* parent, const QString& name);       // a view's picture, `name` proposed
QString ask_matrices_to_export(QWidget* parent, MatrixFormat format);  // shadow_map.glsl, .hlsl or .json
QString ask_scene_to_save(QWidget* parent, const QString& name);       // a JSON referencing the glTF file

}  // namespace shadowlab
