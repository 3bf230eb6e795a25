#pragma once
// The inspector's window, its shell: controls on the left, four linked views in the middle, the
// step player on the right (the full height; the diagnosis under it when shown: the causes of the
// misclassified pixels, their remedies applied in one click), messages (one line until an error)
// and the plot below, the menus and their dialogs (gui/file_dialogs, gui/camera_matrices_dialog). What is open
// is the Session's (model/session: the scene, the inspection shown, a failed open rolled back).
// Every change recomputes the method once, off the GUI thread (BackgroundInspection: the latest
// change wins, a progress line shows work over 100 ms), and the PanelScheduler redraws all views
// from that one Inspection. The method computes with the scene camera's aspect, as the CLI does,
// unless the user unlocks it: then with the Camera panel's shape, recomputed as the panel is resized.
#include <map>
#include <memory>
#include <optional>
#include <QMainWindow>
#include <QTemporaryDir>

#include "gui/background_inspection.hpp"
#include "gui/camera_pose.hpp"
#include "exchange/matrix_export.hpp"
#include "model/session.hpp"

class QAction;
class QDockWidget;
class QMenu;
class QPlainTextEdit;
class QProgressBar;
class QSplitter;
class QTimer;

namespace shadowlab {

class ControlsPanel;
class DiagnosisPanel;
class PanelScheduler;
class ScenePanel;
class PlotPanel;
class StepPlayer;
class ViewPanel;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);

    // A scene JSON, a glTF scene (its own camera and light) or a mesh file (placed on a ground plane,
    // with a camera and a sun); false if it cannot be read: the message names the file and the
    // field, and the current scene stays. A scene read that cannot be inspected is said when its
    // computation lands, and the scene before it comes back.
    bool open_file(const QString& path);
    // An engine's light matrices (GLSL, HLSL or JSON: core/io/matrix_import.hpp): the method becomes
    // `custom` reading them (File ▸ Import light matrices). A file that cannot be read is named in
    // the messages, and the inspection shown stays.
    void import_light_matrices(const QString& file);
    // The same from the clipboard's text (File ▸ Paste light matrices), kept in a file of the
    // window's own for as long as it runs.
    void paste_light_matrices();
    // An engine's camera (view and projection matrices: core/exchange/camera_import.hpp) replaces the
    // scene's, read under `conventions` (key=value: clip_depth, reversed_z, clip_y, looks_along, storage).
    void import_camera_matrices(const QString& file, const std::map<std::string, std::string>& conventions);
    // The scene as a JSON referencing its glTF file, with the camera, light and roles chosen.
    void save_scene(const QString& json_file);

    const Scene& scene() const { return session_.scene(); }
    const Inspection* inspection() const { return session_.inspection(); }  // the one the views show
    // A change's inspection has not landed, or not every panel is drawn from it, or a panel's resize
    // has yet to settle into a change of the Camera view's aspect.
    bool computing() const;
    // How many turns of the event loop have drawn with OpenGL so far (a panel rendered, or presented):
    // what the GUI thread spends on drawing can be told from the rest
    // (tests/gui/window_drag_test.cpp).
    int drawings() const;
    ControlsPanel* controls() const { return controls_; }
    StepPlayer* steps() const { return steps_; }
    PlotPanel* plot() const { return plot_; }
    DiagnosisPanel* diagnosis() const { return diagnosis_; }
    ScenePanel* scene_panel() const { return scene_panel_; }
    const std::vector<ViewPanel*>& panels() const { return panels_; }
    // Compare mode (View > Compare, the toolbar's Compare): the first panel draws configuration A
    // (the Controls'), the second configuration B (the Compare dock's), the third the Difference
    // view; the scene, its camera and light are one, and B's panel draws A's step index.
    void set_compare_mode(bool on);
    bool comparing() const;
    ControlsPanel* compared_controls() const { return compared_controls_; }
    const Inspection* compared() const { return compared_.get(); }  // B's, drawn in compare mode
    ViewPanel* compared_panel() const;                              // B's panel in compare mode, else nullptr
    // The step B's panel draws: A's chosen step's index in B's trace, or B's last where it has fewer
    // steps (empty: B's last).
    std::string compared_step() const;
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
    ViewPanel* camera_panel() const;  // the first panel whose view steers the scene camera (Camera), or nullptr
    void settle_resize();
    void recompute();
    void land(std::shared_ptr<const Inspection> inspection, std::shared_ptr<const Inspection> compared);
    void link_orbits(ViewPanel* moved, const CameraPose& pose);
    std::optional<size_t> chosen_step_index() const;  // A's chosen step in its trace; none: none chosen
    void fail(const QString& why);
    void show_progress();
    void end_progress();
    ViewOptions view_options() const;  // what every panel draws with
    ShownView diagnosed_view(double aspect) const;
    void show_diagnosis();
    void show_before_after_warp();
    void move_light_to(const glm::dvec3& point);
    void put_camera_in_shadow(bool inside);
    void redraw();
    void redraw(ViewPanel* panel);
    void build_view_of(ViewPanel* panel);
    void message(const QString& text, bool error);
    void fit_messages(int lines);
    void open_dialog();
    void export_view(ViewPanel* panel);
    void export_matrices(MatrixFormat format, bool to_clipboard);
    void import_dialog();
    void import_camera_dialog();
    void save_scene_dialog();
    void scene_replaced();
    void choose_from_gltf(const SceneChoice& choice);
    void set_roles(int object, bool casts, bool receives);
    void show_scene_parts();
    void remember_recent(const QString& path);
    void rebuild_recent_menu();
    void restore_settings();

    Session session_;
    BackgroundInspection* computing_;
    PanelScheduler* scheduler_;
    const char* aspect_source_ = "";  // where the newest change's camera aspect came from
    QTimer* progress_timer_;          // while computing: the progress line after 100 ms
    QProgressBar* progress_bar_;
    ControlsPanel* controls_;
    ScenePanel* scene_panel_;
    QAction* save_scene_ = nullptr;
    StepPlayer* steps_;
    PlotPanel* plot_;
    DiagnosisPanel* diagnosis_;
    QDockWidget* diagnosis_dock_ = nullptr;
    bool diagnosis_requested_ = false;  // the newest change's job prepares the Diagnosis dock's error
    bool diagnosis_prepared_ = false;   // ... and the inspection shown had it prepared
    QPlainTextEdit* messages_;
    std::vector<ViewPanel*> panels_;
    QAction* compare_action_ = nullptr;
    ControlsPanel* compared_controls_;
    QDockWidget* compare_dock_ = nullptr;
    std::shared_ptr<const Inspection> compared_;     // B's inspection, landed with A's
    std::vector<const View*> views_before_compare_;  // the panels' views, back when compare mode ends
    std::vector<QSplitter*> splitters_;
    QMenu* recent_menu_ = nullptr;
    QTimer* resize_timer_;  // a resize recomputes or redraws once it settles, not on every step of a drag
    QString last_message_;
    QTemporaryDir pasted_matrices_;  // the clipboard's light matrices, each paste a file of its own
    int pastes_ = 0;
};

}  // namespace shadowlab
