#pragma once
// File ▸ Import camera matrices: an engine's camera file (its view and projection matrices,
// core/io/camera_import.hpp), then the engine's conventions as key=value pairs.
#include <map>
#include <optional>
#include <string>
#include <QString>

class QWidget;

namespace shadowlab {

struct CameraMatricesChoice {
    QString file;
    std::map<std::string, std::string> conventions;  // clip_depth, reversed_z, clip_y, looks_along, storage
};

// Nullopt when the user cancels; throws std::invalid_argument naming a pair that is not key=value.
std::optional<CameraMatricesChoice> ask_camera_matrices(QWidget* parent);

// "clip_depth=zero_to_one, reversed_z=on" as pairs (empty: none, OpenGL's conventions).
std::map<std::string, std::string> conventions_from_text(const QString& text);

}  // namespace shadowlab
