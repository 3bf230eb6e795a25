#pragma once
// The inspector's window: controls on the left, four linked views in the middle, the step player
// on the right (the full height), messages (one line until an error) and the plot below. Every
// change recomputes the method once and redraws all views from that one Inspection. The method
// computes with the scene camera's aspect, as the CLI does, unless the user unlocks it: then with
// the Camera panel's shape, recomputed as the panel is resized.
#include <optional>
#include <QMainWindow>
#include <QTemporaryDir>

#include "io/matrix_export.hpp"
#include "model/inspection.hpp"

class QMenu;
class QPlainTextEdit;
class QSplitter;
class QTimer;

namespace shadowlab {

class ControlsPanel;
class PlotPanel;
class StepPlayer;
class ViewPanel;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);

    // A scene JSON, a glTF scene (its own camera and light) or a mesh file (placed on a ground plane,
    // with a camera and a sun). On failure the message names the file and the field, and the current
    // scene stays.
    bool open_file(const QString& path);
    // An engine's light matrices (GLSL, HLSL or JSON: core/io/matrix_import.hpp): the method becomes
    // `custom` reading them (File ▸ Import light matrices). A file that cannot be read is named in
    // the messages, and the inspection shown stays.
    void import_light_matrices(const QString& file);
    // The same from the clipboard's text (File ▸ Paste light matrices), kept in a file of the
    // window's own for as long as it runs.
    void paste_light_matrices();

    const Scene& scene() const { return scene_; }
    const Inspection* inspection() const { return inspection_ ? &*inspection_ : nullptr; }
    ControlsPanel* controls() const { return controls_; }
    StepPlayer* steps() const { return steps_; }
    PlotPanel* plot() const { return plot_; }
    const std::vector<ViewPanel*>& panels() const { return panels_; }
    QString last_message() const { return last_message_; }

protected:
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;
    void closeEvent(QCloseEvent* event) override;

private:
    // The camera aspect the method computes with, and where it comes from (for the status line).
    struct AspectInForce {
        double aspect;
        const char* source;
    };

    void build_menus();
    AspectInForce aspect_in_force() const;
    ViewPanel* camera_panel() const;  // the first panel showing the Camera view, or nullptr
    void follow_panel_aspect();
    void recompute();
    void show_before_after_warp();
    void move_light_to(const glm::dvec3& point);
    void put_camera_in_shadow(bool inside);
    void redraw();
    void redraw(ViewPanel* panel);
    void message(const QString& text, bool error);
    void fit_messages(int lines);
    void open_dialog();
    void export_view(ViewPanel* panel);
    void export_matrices(MatrixFormat format, bool to_clipboard);
    void import_dialog();
    void remember_recent(const QString& path);
    void rebuild_recent_menu();
    void restore_settings();

    Scene scene_;
    std::optional<Camera> camera_outside_;  // the camera before "Camera in shadow" moved it
    std::optional<Inspection> inspection_;
    ControlsPanel* controls_;
    StepPlayer* steps_;
    PlotPanel* plot_;
    QPlainTextEdit* messages_;
    std::vector<ViewPanel*> panels_;
    std::vector<QSplitter*> splitters_;
    QMenu* recent_menu_ = nullptr;
    QTimer* aspect_timer_;  // a resize recomputes once it settles, not on every step of a drag
    QString last_message_;
    QTemporaryDir pasted_matrices_;  // the clipboard's light matrices, each paste a file of its own
    int pastes_ = 0;
};

}  // namespace shadowlab
