#include "gui/main_window.hpp"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QFileInfo>
#include <QMenuBar>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSignalBlocker>
#include <QSplitter>
#include <QStatusBar>
#include <QTime>
#include <QTimer>
#include <QToolBar>
#include <algorithm>
#include <array>
#include <fstream>
#include <vtkOpenGLRenderWindow.h>

#include "gui/camera_matrices_dialog.hpp"
#include "gui/controls_panel.hpp"
#include "gui/diagnosis_panel.hpp"
#include "gui/file_dialogs.hpp"
#include "gui/panel_scheduler.hpp"
#include "gui/plot_panel.hpp"
#include "gui/scene_panel.hpp"
#include "gui/step_player.hpp"
#include "gui/view_panel.hpp"
#include "exchange/camera_import.hpp"
#include "render/opengl_renderer.hpp"
#include "render/rgb_image.hpp"
#include "views/view_parts.hpp"

namespace shadowlab {
namespace {

constexpr int kMaxRecent = 8;
constexpr int kIdleMessageLines = 1;   // the views get the height
constexpr int kErrorMessageLines = 4;  // an error opens the messages until the next good change
constexpr int kResizeSettleMs = 250;
constexpr int kProgressAfterMs = 100;  // shorter work shows no progress line

QDockWidget* dock(const QString& title, const QString& name, QWidget* content, QMainWindow* window) {
    auto* d = new QDockWidget(title, window);
    d->setObjectName(name);
    d->setWidget(content);
    return d;
}

// A panel that scrolls up and down when the dock is shorter than it: the controls of a method with
// many settings (xpsm's own, then the filter's, the biases and the depth format) stay within a
// 1280 x 800 window instead of growing it. As wide as the panel and its scroll bar, so that it never
// scrolls sideways.
QScrollArea* scrolling(QWidget* content, QWidget* parent) {
    auto* area = new QScrollArea(parent);
    area->setWidget(content);
    area->setWidgetResizable(true);
    area->setFrameShape(QFrame::NoFrame);
    area->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    area->setMinimumWidth(content->minimumSizeHint().width() + area->verticalScrollBar()->sizeHint().width());
    return area;
}

}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      computing_(new BackgroundInspection(this)),
      scheduler_(new PanelScheduler([this](ViewPanel* panel) { build_view_of(panel); }, this)),
      progress_timer_(new QTimer(this)),
      progress_bar_(new QProgressBar(this)),
      controls_(new ControlsPanel(this)),
      scene_panel_(new ScenePanel(this)),
      steps_(new StepPlayer(this)),
      plot_(new PlotPanel(this)),
      diagnosis_(new DiagnosisPanel(this)),
      messages_(new QPlainTextEdit(this)),
      compared_controls_(new ControlsPanel(this)),
      resize_timer_(new QTimer(this)) {
    setWindowTitle("ShadowLab");
    const std::string& renderer = opengl_renderer();
    const bool software = is_software_renderer(renderer);
    if (software) vtkOpenGLRenderWindow::SetGlobalMaximumNumberOfMultiSamples(0);  // before the panels' windows
    setAcceptDrops(true);
    messages_->setReadOnly(true);
    messages_->setObjectName("messages");
    messages_->setLineWrapMode(QPlainTextEdit::NoWrap);  // one message a line: the newest shows when idle
    messages_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    fit_messages(kIdleMessageLines);
    resize_timer_->setSingleShot(true);
    resize_timer_->setInterval(kResizeSettleMs);
    connect(resize_timer_, &QTimer::timeout, this, &MainWindow::settle_resize);
    connect(computing_, &BackgroundInspection::landed, this, &MainWindow::land);
    connect(computing_, &BackgroundInspection::failed, this, &MainWindow::fail);
    connect(computing_, &BackgroundInspection::plotted, this,
            [this](std::shared_ptr<const Plot> plot) { plot_->show_plot(*plot); });
    progress_timer_->setInterval(kProgressAfterMs);
    connect(progress_timer_, &QTimer::timeout, this, &MainWindow::show_progress);
    progress_bar_->setObjectName("progress");
    progress_bar_->setMaximumWidth(160);
    progress_bar_->setTextVisible(false);
    progress_bar_->hide();
    statusBar()->addPermanentWidget(progress_bar_);

    // Four linked views: World | Camera over Light space | Shadow map; each can show any view.
    auto* rows = new QSplitter(Qt::Vertical, this);
    for (const auto& pair : {std::pair{"world", "camera"}, std::pair{"light", "shadowmap"}}) {
        auto* row = new QSplitter(Qt::Horizontal, rows);
        for (const char* v : {pair.first, pair.second}) {
            auto* panel = new ViewPanel(view_or_throw(v), row);
            panels_.push_back(panel);
            connect(panel, &ViewPanel::viewChosen, this, [this] {
                recompute();             // the view may read parts of the inspection not yet made
                resize_timer_->start();  // the Camera view may have moved to another panel
            });
            connect(panel, &ViewPanel::resized, resize_timer_, QOverload<>::of(&QTimer::start));
            connect(panel, &ViewPanel::cameraMoved, this,
                    [this](const glm::dvec3& p, const glm::dvec3& t, const glm::dvec3& u) {
                        session_.orbit_camera(p, t, u);
                        recompute();
                    });
            connect(panel, &ViewPanel::cameraHandleMoved, this, [this](const glm::dvec3& position) {
                session_.move_camera_to(position);
                recompute();
            });
            connect(panel, &ViewPanel::lightHandleMoved, this,
                    [this](const glm::dvec3& point) { move_light_to(point); });
            connect(panel, &ViewPanel::orbitKept, this,
                    [this, panel](const CameraPose& pose) { link_orbits(panel, pose); });
        }
        splitters_.push_back(row);
    }
    splitters_.push_back(rows);
    setCentralWidget(rows);

    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);  // every step of the longest trace shows
    QDockWidget* controls_dock = dock("Controls", "controlsDock", scrolling(controls_, this), this);
    addDockWidget(Qt::LeftDockWidgetArea, controls_dock);
    QDockWidget* scene_dock = dock("Scene", "sceneDock", scene_panel_, this);
    tabifyDockWidget(controls_dock, scene_dock);
    scene_dock->hide();  // View > Scene; shown when a glTF scene opens, whose cameras and lights it picks
    controls_dock->raise();
    addDockWidget(Qt::RightDockWidgetArea, dock("Steps", "stepsDock", steps_, this));
    addDockWidget(Qt::BottomDockWidgetArea, dock("Messages", "messagesDock", messages_, this));
    QDockWidget* plot_dock = dock("Plot", "plotDock", plot_, this);
    addDockWidget(Qt::BottomDockWidgetArea, plot_dock);
    plot_dock->hide();  // measured on demand: View > Plot
    diagnosis_dock_ = dock("Diagnosis", "diagnosisDock", diagnosis_, this);
    addDockWidget(Qt::RightDockWidgetArea, diagnosis_dock_);  // under the steps
    diagnosis_dock_->hide();                                  // its error needs a reference traced: View > Diagnosis
    build_menus();
    compared_controls_->setObjectName("comparedControls");
    compared_controls_->show_the_run_only();
    compare_dock_ = dock("Compare: B", "compareDock", scrolling(compared_controls_, this), this);
    addDockWidget(Qt::LeftDockWidgetArea, compare_dock_);  // under the Controls: A above, B below
    connect(compared_controls_, &ControlsPanel::changed, this, &MainWindow::recompute);
    if (software) message(QString::fromStdString("software OpenGL (" + renderer + "): multisampling off"), false);
    statusBar()->showMessage("drop a scene (.json) or a mesh (.obj, .ply, .stl, .gltf) here, or use File > Open");

    connect(controls_, &ControlsPanel::changed, this, &MainWindow::recompute);
    connect(scene_panel_, &ScenePanel::rolesChanged, this, &MainWindow::set_roles);
    connect(scene_panel_, &ScenePanel::cameraChosen, this, [this](int index) {
        choose_from_gltf({.camera = static_cast<size_t>(index), .light = session_.gltf()->reference.choice.light});
    });
    connect(scene_panel_, &ScenePanel::lightChosen, this, [this](int index) {
        choose_from_gltf({.camera = session_.gltf()->reference.choice.camera, .light = static_cast<size_t>(index)});
    });
    connect(controls_, &ControlsPanel::lightChanged, this, [this] {
        session_.turn_light(controls_->light_direction());
        recompute();
    });
    connect(controls_, &ControlsPanel::cameraInShadowToggled, this, &MainWindow::put_camera_in_shadow);
    connect(controls_, &ControlsPanel::aspectChanged, this, &MainWindow::recompute);
    connect(controls_, &ControlsPanel::shadowOnlyToggled, this, [this] {
        for (ViewPanel* panel : panels_)
            if (panel->view().choosers.shadow_only) redraw(panel);
    });
    connect(steps_, &StepPlayer::stepChosen, this, [this] {  // only the views that draw steps: the
        for (ViewPanel* panel : panels_)                     // Error view would trace its reference again
            if (panel->view().interaction.draws_steps) redraw(panel);
    });
    connect(plot_, &PlotPanel::kindChosen, this, &MainWindow::recompute);
    connect(plot_dock, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible) recompute();
    });
    connect(diagnosis_dock_, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible) recompute();
    });
    connect(diagnosis_, &DiagnosisPanel::remedyChosen, this,
            [this](const InspectionRequest& request, const QString& change) {
                message("remedy applied: " + change, false);
                controls_->set_request(request);
            });
    restore_settings();
    compare_dock_->hide();  // shown by compare mode alone, which starts off
}

void MainWindow::build_menus() {
    QMenu* file = menuBar()->addMenu("&File");
    file->addAction("&Open…", this, &MainWindow::open_dialog, QKeySequence::Open);
    recent_menu_ = file->addMenu("Open &recent");
    rebuild_recent_menu();
    file->addSeparator();
    // One entry per panel, named by the view it shows when the menu opens.
    QMenu* export_menu = file->addMenu("Export view as &PNG");
    connect(export_menu, &QMenu::aboutToShow, this, [this, export_menu] {
        export_menu->clear();
        for (size_t i = 0; i < panels_.size(); ++i) {
            ViewPanel* panel = panels_[i];
            export_menu->addAction(QString("Panel %1: %2…").arg(i + 1).arg(QString::fromStdString(panel->view().title)),
                                   this, [this, panel] { export_view(panel); });
        }
    });
    QMenu* matrices = file->addMenu("Export &matrices");
    for (const auto& [name, format] : {std::pair{"GLSL", MatrixFormat::glsl}, std::pair{"HLSL", MatrixFormat::hlsl},
                                       std::pair{"JSON", MatrixFormat::json}}) {
        const MatrixFormat f = format;
        matrices->addAction(QString("%1 to file…").arg(name), this, [this, f] { export_matrices(f, false); });
        matrices->addAction(QString("%1 to clipboard").arg(name), this, [this, f] { export_matrices(f, true); });
    }
    file->addSeparator();
    file->addAction("&Import light matrices…", this, &MainWindow::import_dialog);
    file->addAction("Paste light matrices", this, &MainWindow::paste_light_matrices);
    file->addAction("Import &camera matrices…", this, &MainWindow::import_camera_dialog);
    save_scene_ = file->addAction("&Save scene…", this, &MainWindow::save_scene_dialog);
    save_scene_->setToolTip("a glTF scene: a scene JSON referencing its file, with the camera, light and roles chosen");
    save_scene_->setEnabled(false);
    file->addAction("&Quit", this, &QWidget::close, QKeySequence::Quit);
    QMenu* view = menuBar()->addMenu("&View");
    for (QDockWidget* d : findChildren<QDockWidget*>()) view->addAction(d->toggleViewAction());
    view->addSeparator();
    QAction* before_after = view->addAction("&Before/after warp", this, &MainWindow::show_before_after_warp);
    before_after->setObjectName("beforeAfterWarp");
    before_after->setToolTip("the lower panels: Light space and PPLS, both from the side");
    compare_action_ = view->addAction("&Compare two configurations");
    compare_action_->setObjectName("compareMode");
    compare_action_->setCheckable(true);
    compare_action_->setToolTip(
        "A (the Controls) beside B (the Compare dock): one scene, camera and light, the same step, and the "
        "Difference view: where their verdicts differ, who is right");
    connect(compare_action_, &QAction::toggled, this, &MainWindow::set_compare_mode);
    QToolBar* toolbar = addToolBar("Compare");
    toolbar->setObjectName("compareToolBar");
    toolbar->addAction(compare_action_);
}

void MainWindow::set_compare_mode(bool on) {
    {
        const QSignalBlocker quiet(compare_action_);
        compare_action_->setChecked(on);
    }
    if (on == comparing()) return;
    if (on) {
        for (ViewPanel* panel : panels_) views_before_compare_.push_back(&panel->view());
        {
            const QSignalBlocker quiet(compared_controls_);
            compared_controls_->set_request(controls_->request());  // B starts as A: change what to compare
        }
        const std::array<const char*, 3> compared_views{"camera", "camera", "difference"};
        for (size_t i = 0; i < compared_views.size(); ++i) panels_[i]->set_view(view_or_throw(compared_views[i]));
        panels_[0]->set_configuration("A");
        panels_[1]->set_configuration("B");
        compare_dock_->show();
        compare_dock_->raise();
        message("compare: panel A draws the Controls' configuration, panel B the Compare dock's", false);
    } else {
        for (size_t i = 0; i < panels_.size(); ++i) panels_[i]->set_view(*views_before_compare_[i]);
        for (ViewPanel* panel : panels_) panel->set_configuration("");
        views_before_compare_.clear();
        compared_.reset();
        compare_dock_->hide();
    }
    recompute();
    resize_timer_->start();  // the Camera view may have moved to another panel
}

bool MainWindow::comparing() const { return !views_before_compare_.empty(); }

ViewPanel* MainWindow::compared_panel() const { return comparing() ? panels_[1] : nullptr; }

std::optional<size_t> MainWindow::chosen_step_index() const {
    const Inspection* a = session_.inspection();
    const std::string chosen = steps_->chosen().toStdString();
    if (!a || chosen.empty()) return std::nullopt;
    const std::vector<Step>& steps = a->trace.steps();
    const auto at = std::find_if(steps.begin(), steps.end(), [&](const Step& s) { return s.id == chosen; });
    if (at == steps.end()) return std::nullopt;
    return static_cast<size_t>(at - steps.begin());
}

std::string MainWindow::compared_step() const {
    const std::optional<size_t> index = chosen_step_index();
    if (!compared_ || !index || *index >= compared_->trace.steps().size()) return "";
    return compared_->trace.steps()[*index].id;
}

// An orbit left in panel A or B moves the other's camera too, when it shows the same view.
void MainWindow::link_orbits(ViewPanel* moved, const CameraPose& pose) {
    if (!comparing()) return;
    ViewPanel* other = moved == panels_[0] ? panels_[1] : moved == panels_[1] ? panels_[0] : nullptr;
    if (!other || other->view() != moved->view()) return;
    other->keep_camera(pose);
    redraw(other);
}

bool MainWindow::open_file(const QString& path) {
    try {
        for (const std::string& note : session_.open_file(path.toStdString()))
            message(QString::fromStdString(note), false);
    } catch (const std::exception& e) {
        message(QString::fromStdString(e.what()), true);
        return false;
    }
    scene_replaced();
    return true;
}

// A scene on trial in the session: the controls and panels start from it.
void MainWindow::scene_replaced() {
    controls_->set_light_direction(session_.scene().light.direction);
    controls_->clear_camera_in_shadow();
    for (ViewPanel* panel : panels_) panel->forget_camera();
    show_scene_parts();
    recompute();
}

void MainWindow::show_scene_parts() {
    const std::optional<GltfSource>& gltf = session_.gltf();
    scene_panel_->set_scene(session_.scene(), gltf ? &gltf->contents : nullptr,
                            gltf ? gltf->reference.choice : SceneChoice{});
    save_scene_->setEnabled(gltf.has_value());
    if (gltf) findChild<QDockWidget*>("sceneDock")->show();
}

// Another camera or light of the glTF file: the scene read again with it, the roles kept.
void MainWindow::choose_from_gltf(const SceneChoice& choice) {
    try {
        for (const std::string& assumed : session_.choose_from_gltf(choice))
            message(QString::fromStdString(assumed), false);
    } catch (const std::exception& e) {
        message(QString::fromStdString(e.what()), true);
        show_scene_parts();  // the chooser back to the choice in force
        return;
    }
    scene_replaced();
}

// An object marked as casting or receiving (or neither); refused, with the reason, if the scene
// would break a rule (a light inside a mesh that casts).
void MainWindow::set_roles(int object, bool casts, bool receives) {
    try {
        session_.set_roles(static_cast<size_t>(object), casts, receives);
    } catch (const std::exception& e) {
        message(QString::fromStdString(e.what()), true);
        show_scene_parts();
        return;
    }
    recompute();
}

MainWindow::AspectInForce MainWindow::aspect_in_force() const {
    const double scene_aspect = session_.scene().camera.aspect;
    if (controls_->aspect_locked()) return {scene_aspect, "the scene"};
    const ViewPanel* panel = camera_panel();
    const QSize size = panel ? panel->drawing_size() : QSize();
    if (size.isEmpty()) return {scene_aspect, "the scene (no Camera panel to follow)"};
    return {static_cast<double>(size.width()) / size.height(), "the Camera panel"};
}

ViewPanel* MainWindow::camera_panel() const {
    for (ViewPanel* panel : panels_)
        if (panel->view().interaction.drag == ViewDrag::steers_scene_camera) return panel;
    return nullptr;
}

// Once a resize of the panels settles: unlocked, the aspect follows the Camera panel, recomputed if
// it changed; else the panels are built again for their new sizes (a space view frames its region
// for the panel's shape, an image view fits its pixels).
void MainWindow::settle_resize() {
    if (!session_.inspection()) return;
    if (aspect_in_force().aspect != session_.inspection()->scene.camera.aspect)
        recompute();
    else
        redraw();
}

int MainWindow::drawings() const { return scheduler_->drawings(); }

bool MainWindow::computing() const {
    return computing_->busy() || scheduler_->busy() || resize_timer_->isActive();  // the last: a change to come
}

void MainWindow::recompute() {
    if (session_.scene().objects.empty()) return;
    const AspectInForce aspect = aspect_in_force();
    InspectionJob job{.scene = session_.scene(),
                      .request = controls_->request(),
                      .shown = {},
                      .plot = {},
                      .before = session_.shown()};
    job.scene.camera.aspect = aspect.aspect;
    if (comparing()) job.compared = compared_controls_->request();
    for (ViewPanel* panel : panels_)
        job.shown.push_back(
            {&panel->view(), panel->options_for(view_options(), aspect.aspect), panel == compared_panel()});
    diagnosis_requested_ = diagnosis_dock_->isVisible();
    if (diagnosis_requested_) job.diagnosis = diagnosed_view(aspect.aspect);
    const Method* method = find_method(job.request.method);
    if (plot_->isVisible() && method && method->makes_maps())
        job.plot = plot_->request(job.scene, job.request.method, job.request.settings, job.request.resolution);
    aspect_source_ = aspect.source;
    computing_->submit(std::move(job));
    progress_timer_->start();
}

// Work over 100 ms: a progress bar by phases, and the phase in the status line.
void MainWindow::show_progress() {
    if (!computing_->busy()) return end_progress();
    const JobProgress progress = computing_->progress();
    progress_bar_->setRange(0, progress.total);
    progress_bar_->setValue(progress.done);
    progress_bar_->show();
    statusBar()->showMessage(QString::fromStdString(progress.phase) + "…");
}

void MainWindow::end_progress() {
    progress_timer_->stop();
    progress_bar_->hide();
}

// The newest change's inspection: every view redraws from it.
void MainWindow::land(std::shared_ptr<const Inspection> inspection, std::shared_ptr<const Inspection> compared) {
    compared_ = comparing() ? std::move(compared) : nullptr;
    if (!computing_->busy()) end_progress();  // else the plot is still measured: the timer ends it
    fit_messages(kIdleMessageLines);
    if (const std::optional<std::string> opened = session_.land(std::move(inspection))) {
        const QString path = QString::fromStdString(*opened);
        remember_recent(path);
        setWindowTitle("ShadowLab — " + QFileInfo(path).fileName());
        message("opened " + path + " (" + QString::number(session_.scene().objects.size()) + " objects)", false);
    }
    const Inspection& shown = *session_.inspection();
    steps_->set_trace(shown.trace);
    const std::string bias = shown.bias < 0.0 ? "slope-scaled" : std::to_string(shown.bias);
    const std::string what = shown.has_map() ? std::to_string(shown.resolution) + "² map, bias " + bias
                                             : std::to_string(shown.image_width) + "x" +
                                                   std::to_string(shown.image_height) + " camera image judged";
    const std::string notes_label = shown.has_map() ? "fallback: " : "limits: ";
    const std::vector<Note>& notes = shown.notes();
    const std::string told = notes_label + (notes.empty() ? "none" : describe(notes));
    statusBar()->showMessage(
        QString::fromStdString(shown.title() + " — " + what + " — " + told) +
        QString(" — aspect %1 from %2").arg(shown.scene.camera.aspect, 0, 'f', 2).arg(aspect_source_));
    if (!notes.empty()) message(QString::fromStdString(told), false);
    if (compared_ && !compared_->notes().empty())
        message(QString::fromStdString("B: " + compared_->name() + ": " + describe(compared_->notes())), false);
    diagnosis_prepared_ = diagnosis_requested_;  // the job that landed is the newest submitted
    redraw();
}

// The Error view the Diagnosis dock reads: a panel's that shows it (the pixels its legend counts),
// else the Error view at its own size.
ShownView MainWindow::diagnosed_view(double aspect) const {
    const View& error = view_or_throw("error");
    for (ViewPanel* panel : panels_)
        if (panel->view() == error) return {&error, panel->options_for(view_options(), aspect)};
    return {&error, ViewOptions{}};
}

// The causes of the inspection shown, in the pixels the Error panel draws now: those its job
// prepared, or, a panel resized since, those the panel itself will judge.
void MainWindow::show_diagnosis() {
    if (!diagnosis_prepared_ || !diagnosis_dock_->isVisible()) return;
    const Inspection& shown = *session_.inspection();
    const ShownView diagnosed = diagnosed_view(shown.scene.camera.aspect);
    const glm::ivec2 size = judged_image_size(shown, diagnosed.options);
    diagnosis_->show_diagnosis(shown, shown.error(size.x, size.y));
}

// The newest change cannot be inspected: said, the views keep the last inspection, and a scene just
// opened gives way to the one before it.
void MainWindow::fail(const QString& why) {
    end_progress();
    message(why, true);
    if (!session_.fail()) return;
    controls_->set_light_direction(session_.scene().light.direction);
    show_scene_parts();
    recompute();
}

// Into a caster's shadow volume (z-pass fails there, z-fail holds), or back where the camera was.
void MainWindow::put_camera_in_shadow(bool inside) {
    if (!session_.put_camera_in_shadow(inside)) {
        controls_->clear_camera_in_shadow();
        return message("camera in shadow: no caster's shadow has room for the camera above the ground", true);
    }
    recompute();
}

// A directional light now shines from `point` toward the scene's centre; others move there.
void MainWindow::move_light_to(const glm::dvec3& point) {
    session_.move_light_to(point);
    controls_->set_light_direction(session_.scene().light.direction);
    recompute();
}

// Every panel from the inspection shown.
void MainWindow::redraw() {
    show_diagnosis();
    for (ViewPanel* panel : panels_) redraw(panel);
}

void MainWindow::redraw(ViewPanel* panel) { scheduler_->redraw(panel); }

ViewOptions MainWindow::view_options() const {
    ViewOptions options;
    options.step = steps_->chosen().toStdString();
    options.lit_mask = controls_->shadow_only();
    return options;
}

// Panel B in compare mode draws B at A's step index (its last where it has fewer steps); every
// panel's options name the other configuration (the Difference view's).
void MainWindow::build_view_of(ViewPanel* panel) {
    if (!session_.inspection()) return;
    const bool of_b = compared_ && panel == compared_panel();
    ViewOptions options = view_options();
    options.compared = of_b ? session_.shown() : compared_;
    if (of_b) {
        options.step = compared_step();
        const std::optional<size_t> index = chosen_step_index();
        if (index && *index >= compared_->trace.steps().size() && panel->view().interaction.draws_steps)
            message(QString("B: %1 has no step %2 (it has %3): its last step shown")
                        .arg(QString::fromStdString(compared_->name()))
                        .arg(*index + 1)
                        .arg(compared_->trace.steps().size()),
                    false);
    }
    try {
        for (const std::string& note : panel->show(of_b ? *compared_ : *session_.inspection(), options).notes)
            message(QString::fromStdString(panel->view().title + ": " + note), false);
    } catch (const std::exception& e) {
        message(QString::fromStdString(e.what()), true);
    }
}

void MainWindow::message(const QString& text, bool error) {
    last_message_ = text;
    messages_->appendPlainText(QTime::currentTime().toString("HH:mm:ss ") + (error ? "error: " : "") + text);
    messages_->moveCursor(QTextCursor::End);  // the newest line shows
    messages_->ensureCursorVisible();
    if (!error) return;
    statusBar()->showMessage("error: " + text);
    fit_messages(kErrorMessageLines);
}

void MainWindow::fit_messages(int lines) {
    const int margins = 2 * (messages_->frameWidth() + static_cast<int>(messages_->document()->documentMargin()));
    messages_->setFixedHeight(lines * messages_->fontMetrics().lineSpacing() + margins);
}

// Light space beside PPLS in the lower panels, both from the side: the scene before and after the warp.
void MainWindow::show_before_after_warp() {
    for (const auto& [panel, view] : {std::pair{panels_[2], "light"}, std::pair{panels_[3], "ppls"}}) {
        panel->set_view(view_or_throw(view));
        panel->set_preset(SpacePreset::side);
        redraw(panel);
    }
}

void MainWindow::open_dialog() {
    const QString path = ask_scene_to_open(this);
    if (!path.isEmpty()) open_file(path);
}

void MainWindow::export_view(ViewPanel* panel) {
    const QString name = QString::fromStdString(panel->view().name) + ".png";
    const QString path = ask_png_to_export(this, name);
    if (path.isEmpty()) return;
    try {
        write_png(panel->grab(), path.toStdString());
        message("wrote " + path, false);
    } catch (const std::exception& e) {
        message(QString::fromStdString(e.what()), true);
    }
}

void MainWindow::export_matrices(MatrixFormat format, bool to_clipboard) {
    const Inspection* shown = session_.inspection();
    if (!shown) return;
    if (!shown->has_map()) return message(QString::fromStdString(shown->name() + " has no shadow-map matrices"), true);
    const QString text = QString::fromStdString(shadowlab::export_matrices(shown->method->name, shown->setup, format));
    if (to_clipboard) {
        QApplication::clipboard()->setText(text);
        return message("matrices copied to the clipboard", false);
    }
    const QString path = ask_matrices_to_export(this, format);
    if (path.isEmpty()) return;
    std::ofstream out(path.toStdString());
    out << text.toStdString();
    message(out ? "wrote " + path : "cannot write " + path, !out);
}

void MainWindow::import_dialog() {
    const QString path = ask_light_matrices_to_import(this);
    if (!path.isEmpty()) import_light_matrices(path);
}

void MainWindow::import_light_matrices(const QString& file) {
    controls_->set_method("custom");
    if (!controls_->set_text_setting("matrices", file)) message("the custom method takes no matrices file", true);
}

void MainWindow::paste_light_matrices() {
    if (!pasted_matrices_.isValid()) return message("no temporary directory to keep the pasted matrices in", true);
    const QString path = pasted_matrices_.filePath(QString("pasted_%1.txt").arg(++pastes_));
    std::ofstream out(path.toStdString());
    out << QApplication::clipboard()->text().toStdString();
    if (!out) return message("cannot write " + path, true);
    out.close();
    import_light_matrices(path);
}

void MainWindow::import_camera_dialog() {
    try {
        if (const std::optional<CameraMatricesChoice> chosen = ask_camera_matrices(this))
            import_camera_matrices(chosen->file, chosen->conventions);
    } catch (const std::exception& e) {
        message(QString::fromStdString(e.what()), true);
    }
}

void MainWindow::import_camera_matrices(const QString& file, const std::map<std::string, std::string>& conventions) {
    try {
        session_.replace_camera(
            import_camera(file.toStdString(), camera_conventions_from(conventions), session_.scene().bounds()));
        controls_->clear_camera_in_shadow();
        for (ViewPanel* panel : panels_) panel->forget_camera();
        message("camera from " + file, false);
        recompute();
    } catch (const std::exception& e) {
        message(QString::fromStdString(e.what()), true);
    }
}

void MainWindow::save_scene_dialog() {
    if (!session_.gltf()) return;
    const QString path = ask_scene_to_save(this, QString::fromStdString(session_.scene().name));
    if (!path.isEmpty()) save_scene(path);
}

void MainWindow::save_scene(const QString& json_file) {
    try {
        session_.save_scene(json_file.toStdString());
        message("wrote " + json_file, false);
    } catch (const std::exception& e) {
        message(QString::fromStdString(e.what()), true);
    }
}

void MainWindow::remember_recent(const QString& path) {
    QSettings settings;
    QStringList recent = settings.value("recentFiles").toStringList();
    recent.removeAll(QFileInfo(path).absoluteFilePath());
    recent.prepend(QFileInfo(path).absoluteFilePath());
    settings.setValue("recentFiles", QStringList(recent.mid(0, kMaxRecent)));
    rebuild_recent_menu();
}

void MainWindow::rebuild_recent_menu() {
    recent_menu_->clear();
    for (const QString& path : QSettings().value("recentFiles").toStringList())
        recent_menu_->addAction(path, this, [this, path] { open_file(path); });
    recent_menu_->setEnabled(!recent_menu_->isEmpty());
}

void MainWindow::restore_settings() {
    QSettings settings;
    restoreGeometry(settings.value("geometry").toByteArray());
    restoreState(settings.value("windowState").toByteArray());
    for (size_t i = 0; i < splitters_.size(); ++i)
        splitters_[i]->restoreState(settings.value(QString("splitter%1").arg(i)).toByteArray());
    for (size_t i = 0; i < panels_.size(); ++i) {
        const View* view = find_view(settings.value(QString("panel%1").arg(i)).toString().toStdString());
        if (view) panels_[i]->set_view(*view);
    }
    controls_->set_method(settings.value("method", "focused").toString());
    controls_->set_resolution(settings.value("resolution", 1024).toInt());
}

void MainWindow::closeEvent(QCloseEvent* event) {
    QSettings settings;
    settings.setValue("geometry", saveGeometry());
    settings.setValue("windowState", saveState());
    for (size_t i = 0; i < splitters_.size(); ++i)
        settings.setValue(QString("splitter%1").arg(i), splitters_[i]->saveState());
    for (size_t i = 0; i < panels_.size(); ++i) {  // in compare mode, the views it will give back
        const View& shown = comparing() ? *views_before_compare_[i] : panels_[i]->view();
        settings.setValue(QString("panel%1").arg(i), QString::fromStdString(shown.name));
    }
    const InspectionRequest request = controls_->request();
    settings.setValue("method", QString::fromStdString(request.method));
    settings.setValue("resolution", request.resolution);
    event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    const QList<QUrl> urls = event->mimeData()->urls();
    if (!urls.isEmpty()) open_file(urls.front().toLocalFile());
}

}  // namespace shadowlab
