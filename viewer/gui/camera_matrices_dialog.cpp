#include "gui/camera_matrices_dialog.hpp"

#include <QFileDialog>
#include <QInputDialog>
#include <QLineEdit>
#include <QStringList>
#include <stdexcept>

namespace shadowlab {

std::optional<CameraMatricesChoice> ask_camera_matrices(QWidget* parent) {
    const QString path =
        QFileDialog::getOpenFileName(parent, "Import an engine's camera (view and projection)", QString(),
                                     "Camera matrices (*.glsl *.hlsl *.json *.txt);;All files (*)");
    if (path.isEmpty()) return std::nullopt;
    bool ok = false;
    const QString text =
        QInputDialog::getText(parent, "The engine's conventions",
                              "key=value, comma-separated (empty: OpenGL's), e.g. clip_depth=zero_to_one, "
                              "reversed_z=on, clip_y=down, looks_along=plus_z",
                              QLineEdit::Normal, QString(), &ok);
    if (!ok) return std::nullopt;
    return CameraMatricesChoice{.file = path, .conventions = conventions_from_text(text)};
}

std::map<std::string, std::string> conventions_from_text(const QString& text) {
    std::map<std::string, std::string> conventions;
    for (const QString& pair : text.split(',', Qt::SkipEmptyParts)) {
        const QStringList kv = pair.split('=');
        if (kv.size() != 2)
            throw std::invalid_argument("camera conventions: expected key=value, got '" + pair.trimmed().toStdString() +
                                        "'");
        conventions[kv[0].trimmed().toStdString()] = kv[1].trimmed().toStdString();
    }
    return conventions;
}

}  // namespace shadowlab
