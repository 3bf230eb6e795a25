// The window as a user drives it: switching the method changes what the views draw; a bad file
// is reported by name and field while the previous scene stays; a mesh alone becomes a scene; the
// step list fits at 1280 x 800 and shows matrices as aligned grids; the window's matrices are the
// CLI's; an engine's light matrices imported or pasted give the same map; an orbit survives a change
// of step; the messages take one line until an error.
#include <fstream>
#include <sstream>

#include <QAction>
#include <QCheckBox>
#include <QClipboard>
#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QListWidget>
#include <QProcess>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollBar>
#include <QSettings>
#include <QStatusBar>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTextBlock>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>
#include <glm/gtc/type_ptr.hpp>
#include <vtkCamera.h>
#include <vtkInteractorObserver.h>
#include <vtkPropCollection.h>
#include <vtkProperty.h>
#include <vtkSphereHandleRepresentation.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>

#include "qt_test_main.hpp"
#include "settled.hpp"
#include "gltf_support.hpp"
#include "scene/scene_loader.hpp"
#include "gui/camera_pose.hpp"
#include "gui/controls_panel.hpp"
#include "gui/main_window.hpp"
#include "gui/plot_panel.hpp"
#include "gui/scene_panel.hpp"
#include "plot/shimmer_chart.hpp"
#include "gui/step_player.hpp"
#include "gui/view_panel.hpp"
#include "exchange/inspection_json.hpp"
#include "maps/clip_conventions.hpp"
#include "math/matrix.hpp"
#include "views/difference_colours.hpp"

using namespace shadowlab;
using shadowlab::testing::settled;

namespace {

QString source(const char* relative) { return QString(SHADOWLAB_SOURCE_DIR) + "/" + relative; }

// The share of pixels that differ between two grabs of the same size.
double changed_share(const RgbImage& a, const RgbImage& b) {
    if (a.width != b.width || a.height != b.height) return 1.0;
    size_t changed = 0;
    for (size_t i = 0; i < a.rgb.size(); i += 3)
        changed += a.rgb[i] != b.rgb[i] || a.rgb[i + 1] != b.rgb[i + 1] || a.rgb[i + 2] != b.rgb[i + 2];
    return static_cast<double>(changed) / (a.rgb.size() / 3);
}

// The share of pixels that differ within the letterboxed picture of `a` (the box of pixels unlike
// its top-left corner, the backdrop), so that the panel's shape does not weigh in.
double changed_share_in_picture(const RgbImage& a, const RgbImage& b) {
    int x0 = a.width, y0 = a.height, x1 = -1, y1 = -1;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            if (!std::equal(a.at(x, y), a.at(x, y) + 3, a.at(0, 0)))
                x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
    if (x1 < 0 || a.width != b.width || a.height != b.height) return changed_share(a, b);
    size_t changed = 0;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) changed += !std::equal(a.at(x, y), a.at(x, y) + 3, b.at(x, y));
    return static_cast<double>(changed) / ((x1 - x0 + 1) * (y1 - y0 + 1));
}

// An image of the same size filled with its top-left pixel's colour (the background).
RgbImage flat_like(const RgbImage& image) {
    RgbImage flat(image.width, image.height);
    for (size_t i = 0; i < flat.rgb.size(); i += 3) std::copy_n(image.rgb.begin(), 3, flat.rgb.begin() + i);
    return flat;
}

// The map matrix `shadowlab inspect --json` prints for the scene, method and settings (rows);
// throws with the CLI's error output if it fails.
glm::dmat4 cli_world_to_uvz(const QString& scene, const InspectionRequest& request) {
    QStringList arguments{"inspect", scene, "--method", QString::fromStdString(request.method), "--json"};
    for (const auto& [key, value] : request.settings) arguments << "--set" << QString::fromStdString(key + "=" + value);
    QProcess cli;
    cli.start(SHADOWLAB_CLI, arguments);
    if (!cli.waitForFinished(60000) || cli.exitCode() != 0)
        throw std::runtime_error(request.method + ": " + cli.readAllStandardError().toStdString());
    const Json rows = Json::parse(cli.readAllStandardOutput().toStdString())["maps"][0]["world_to_uvz"];
    glm::dmat4 m;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m[c][r] = rows[r][c].get<double>();
    return m;
}

// A grid's text as numbers, cells[row][column], and where each line's cells end (right-aligned
// columns end at the same character on every line).
struct ParsedGrid {
    double cells[4][4];
    std::vector<std::vector<qsizetype>> cell_ends;
};

std::optional<ParsedGrid> parse_grid(const QStringList& lines) {
    if (lines.size() != 4) return std::nullopt;
    ParsedGrid grid{.cells = {}, .cell_ends = std::vector<std::vector<qsizetype>>(4)};
    const QRegularExpression number("\\S+");
    for (int r = 0; r < 4; ++r) {
        int c = 0;
        for (auto match = number.globalMatch(lines[r]); match.hasNext(); ++c) {
            const QRegularExpressionMatch cell = match.next();
            bool ok = false;
            if (c < 4) grid.cells[r][c] = cell.captured().toDouble(&ok);
            if (!ok) return std::nullopt;
            grid.cell_ends[r].push_back(cell.capturedEnd());
        }
        if (c != 4) return std::nullopt;
    }
    return grid;
}

bool same_direction(const CameraPose& a, const CameraPose& b) {
    constexpr double kClose = 1e-9;
    const glm::dvec3 a_looks = glm::normalize(a.focal_point - a.position),
                     b_looks = glm::normalize(b.focal_point - b.position);
    return glm::length(a.focal_point - b.focal_point) < kClose * std::max(1.0, glm::length(a.focal_point)) &&
           glm::length(a_looks - b_looks) < kClose && glm::length(a.view_up - b.view_up) < kClose &&
           a.parallel_projection == b.parallel_projection;
}

bool same_pose(const CameraPose& a, const CameraPose& b) {
    constexpr double kClose = 1e-9;
    return glm::length(a.position - b.position) < kClose * std::max(1.0, glm::length(a.position)) &&
           glm::length(a.focal_point - b.focal_point) < kClose * std::max(1.0, glm::length(a.focal_point)) &&
           glm::length(a.view_up - b.view_up) < kClose && std::abs(a.view_angle - b.view_angle) < kClose &&
           std::abs(a.parallel_scale - b.parallel_scale) < kClose * a.parallel_scale &&
           a.parallel_projection == b.parallel_projection;
}

vtkRenderWindow* render_window(ViewPanel* panel) { return panel->findChild<QVTKOpenGLNativeWidget*>()->renderWindow(); }

vtkCamera* view_camera(ViewPanel* panel) {
    return render_window(panel)->GetRenderers()->GetFirstRenderer()->GetActiveCamera();
}

// A world point's display position in a renderer (VTK's: pixels from the bottom left).
glm::dvec2 display_of(vtkRenderer* renderer, const double* world) {
    double display[3];
    vtkInteractorObserver::ComputeWorldToDisplay(renderer, world[0], world[1], world[2], display);
    return {display[0], display[1]};
}

// A sphere handle's radius on screen, in pixels: its centre to a point of its rim across the view.
double on_screen_radius(vtkRenderer* renderer, vtkSphereHandleRepresentation* ball) {
    const glm::dvec3 centre = glm::make_vec3(ball->GetWorldPosition());
    const double* up = renderer->GetActiveCamera()->GetViewUp();
    const glm::dvec3 rim = centre + ball->GetSphereRadius() * glm::normalize(glm::make_vec3(up));
    return glm::length(display_of(renderer, glm::value_ptr(rim)) - display_of(renderer, glm::value_ptr(centre)));
}

// A left-button drag on a VTK widget from a display position by `by` pixels (right and up), as
// Qt delivers it: press, moves, release.
void drag(QWidget* widget, const glm::dvec2& display, const QPoint& by) {
    const QPoint from(static_cast<int>(display.x), widget->height() - 1 - static_cast<int>(display.y));
    const auto send = [&](QEvent::Type type, const QPoint& at, Qt::MouseButtons held) {
        QMouseEvent event(type, at, Qt::LeftButton, held, Qt::NoModifier);
        QApplication::sendEvent(widget, &event);
    };
    send(QEvent::MouseButtonPress, from, Qt::LeftButton);
    for (int step = 1; step <= 5; ++step)
        send(QEvent::MouseMove, from + QPoint(by.x() * step / 5, -by.y() * step / 5), Qt::LeftButton);
    send(QEvent::MouseButtonRelease, from + QPoint(by.x(), -by.y()), Qt::NoButton);
}

}  // namespace

class MainWindowTest : public QObject {
    Q_OBJECT
    std::unique_ptr<MainWindow> window_;

    ViewPanel* panel_showing(const View& view) {
        for (ViewPanel* p : window_->panels())
            if (p->view() == view) return p;
        return nullptr;
    }

private slots:
    void init() {
        QSettings().clear();  // a fresh layout, not the last test's
        window_ = std::make_unique<MainWindow>();
        window_->resize(1400, 900);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
        QVERIFY(window_->open_file(source("data/scenes/box_on_plane.json")));
        QVERIFY(settled(*window_));
    }
    void cleanup() { window_.reset(); }

    void switchingTheMethodChangesTheViews() {
        ViewPanel* light = panel_showing(view_or_throw("light"));
        ViewPanel* map = panel_showing(view_or_throw("shadowmap"));
        QVERIFY(light && map);
        const RgbImage light_before = light->grab(), map_before = map->grab();
        QComboBox* selector = window_->controls()->method_selector();
        selector->setCurrentIndex(selector->findData("lispsm"));
        QVERIFY(settled(*window_));
        QCOMPARE(QString::fromStdString(window_->inspection()->method->name), QString("lispsm"));
        QVERIFY2(changed_share(light_before, light->grab()) > 0.01, "the Light space view did not change");
        QVERIFY2(changed_share(map_before, map->grab()) > 0.05, "the Shadow map view did not change");
        QVERIFY(window_->steps()->chosen().size() > 0);
    }

    void aBadFileIsReportedAndTheSceneStays() {
        const Inspection* shown = window_->inspection();
        QVERIFY(!window_->open_file(source("tests/data/bad/negative_size.json")));
        QVERIFY2(window_->last_message().contains("negative_size.json"), qPrintable(window_->last_message()));
        QVERIFY2(window_->last_message().contains("objects[1].size"), qPrintable(window_->last_message()));
        QCOMPARE(QString::fromStdString(window_->scene().name), QString("box_on_plane"));
        QVERIFY(settled(*window_));
        QVERIFY2(window_->inspection() == shown, "the views were given another inspection after a failed open");
    }

    void methodAndViewsAreRememberedBetweenRuns() {
        QComboBox* selector = window_->controls()->method_selector();
        selector->setCurrentIndex(selector->findData("lispsm"));
        window_->panels()[0]->set_view(view_or_throw("ppls"));
        window_->close();  // saves the settings
        MainWindow next;
        QCOMPARE(QString::fromStdString(next.controls()->request().method), QString("lispsm"));
        QCOMPARE(QString::fromStdString(next.panels()[0]->view().name), QString("ppls"));
    }

    void aMeshAloneGetsAGroundACameraAndASun() {
        QVERIFY(window_->open_file(source("data/meshes/tetrahedron.obj")));
        QCOMPARE(window_->scene().objects.size(), size_t(2));
        QCOMPARE(QString::fromStdString(window_->scene().name), QString("tetrahedron"));
    }

    void draggingTheLightHandleTurnsTheLight() {
        ViewPanel* world = panel_showing(view_or_throw("world"));
        ViewPanel* camera = panel_showing(view_or_throw("camera"));
        const RgbImage before = camera->grab();
        emit world->lightHandleMoved({30.0, 8.0, 0.0});  // dropped low on +x: the light now runs toward -x
        QVERIFY(settled(*window_));
        const glm::dvec3 d = window_->scene().light.direction;
        QVERIFY2(d.x < -0.9 && d.y < 0.0, qPrintable(QString("light direction %1 %2 %3").arg(d.x).arg(d.y).arg(d.z)));
        QVERIFY2(changed_share(before, camera->grab()) > 0.01, "the shadows did not move");
    }

    // The World view's light and camera handles are balls of one size on screen, a tiny model's or
    // a huge one's (they were sized by the scene's extent: invisible on the first, covering the
    // second), and a ball is still picked and dragged: its drop turns the light.
    void theHandlesKeepTheirSizeOnScreenAndStillDrag() {
        QTemporaryDir dir;
        for (const double scale : {0.01, 1000.0}) {
            const QString file = dir.filePath(QString("tetrahedron_%1.obj").arg(scale));
            std::ofstream(file.toStdString())
                << "v " << -0.5 * scale << " 0 " << -0.5 * scale << "\nv " << 0.5 * scale << " 0 " << -0.5 * scale
                << "\nv 0 0 " << 0.5 * scale << "\nv 0 " << scale << " 0\nf 1 2 3\nf 1 4 2\nf 2 4 3\nf 3 4 1\n";
            QVERIFY(window_->open_file(file));
            QVERIFY(settled(*window_));
            ViewPanel* world = panel_showing(view_or_throw("world"));
            world->grab();  // rendered: the balls are sized for the view's camera
            vtkRenderer* renderer = render_window(world)->GetRenderers()->GetFirstRenderer();
            std::vector<vtkSphereHandleRepresentation*> balls;
            vtkPropCollection* props = renderer->GetViewProps();
            props->InitTraversal();
            while (vtkProp* prop = props->GetNextProp())
                if (auto* ball = vtkSphereHandleRepresentation::SafeDownCast(prop)) balls.push_back(ball);
            QCOMPARE(balls.size(), size_t(2));
            for (vtkSphereHandleRepresentation* ball : balls) {
                const double radius = on_screen_radius(renderer, ball);
                QVERIFY2(radius > 6.0 && radius < 20.0,
                         qPrintable(QString("a ball %1 px across at scale %2").arg(2.0 * radius).arg(scale)));
            }
            vtkSphereHandleRepresentation* light = balls[0]->GetProperty()->GetColor()[2] < 0.5 ? balls[0] : balls[1];
            const glm::dvec3 start = glm::make_vec3(light->GetWorldPosition());
            std::vector<glm::dvec3> drops;
            const QMetaObject::Connection dropped =
                connect(world, &ViewPanel::lightHandleMoved, [&](const glm::dvec3& at) { drops.push_back(at); });
            drag(world->findChild<QVTKOpenGLNativeWidget*>(), display_of(renderer, glm::value_ptr(start)), {30, 20});
            disconnect(dropped);
            QCOMPARE(drops.size(), size_t(1));
            QVERIFY2(glm::length(drops[0] - start) > 1e-3 * scale, "the ball was dropped where it was picked");
            QVERIFY(settled(*window_));
        }
    }

    // Volumes draw real stencil shadows in the window's Camera view: with the camera moved into a
    // shadow, z-pass and z-fail give clearly different pictures (z-pass inverts the shadows).
    void volumesDrawStencilShadowsAndTheCameraInShadowBreaksZPass() {
        QVERIFY(window_->open_file(source("data/scenes/volumes.json")));
        QVERIFY(settled(*window_));
        ViewPanel* camera = panel_showing(view_or_throw("camera"));
        const RgbImage map_image = camera->grab();
        const glm::dvec3 outside = window_->scene().camera.position;
        QComboBox* selector = window_->controls()->method_selector();
        selector->setCurrentIndex(selector->findData("volumes"));
        QVERIFY(settled(*window_));
        QVERIFY(window_->inspection()->geometry.has_value());
        QVERIFY2(changed_share(map_image, camera->grab()) > 0.0005, "the Camera view did not change for volumes");
        auto* inside = window_->controls()->findChild<QCheckBox*>("cameraInShadow");
        QVERIFY(inside);
        inside->setChecked(true);
        QVERIFY(settled(*window_));
        QVERIFY(window_->scene().camera.position != outside);
        const RgbImage zfail = camera->grab();
        auto* count = window_->controls()->findChild<QComboBox*>("count");
        QVERIFY(count);
        count->setCurrentText("zpass");
        QVERIFY(settled(*window_));
        const double differ = changed_share_in_picture(zfail, camera->grab());
        QVERIFY2(differ > 0.2, qPrintable(QString("z-pass and z-fail differ at only %1 of the pixels").arg(differ)));
        inside->setChecked(false);
        QVERIFY(settled(*window_));
        QVERIFY(window_->scene().camera.position == outside);
    }

    // Every method and technique in every view of one panel: something is drawn (not one flat
    // colour), and nothing throws or crashes.
    void everyMethodDrawsEveryView() {
        ViewPanel* panel = window_->panels()[0];
        QComboBox* selector = window_->controls()->method_selector();
        for (int m = 0; m < selector->count(); ++m) {
            if (selector->itemData(m).toString().isEmpty()) continue;  // the separator
            selector->setCurrentIndex(m);
            QVERIFY(settled(*window_));
            for (const View& view : all_views()) {
                panel->set_view(view);
                emit panel->viewChosen();
                QVERIFY(settled(*window_));
                const RgbImage image = panel->grab();
                const double drawn = changed_share(image, flat_like(image));
                QVERIFY2(drawn > 0.01,
                         qPrintable(selector->itemData(m).toString() + " in " + QString::fromStdString(view.title) +
                                    ": the panel is one flat colour"));
            }
        }
    }

    // At 1280 x 800 the step list shows every step of XPSM, the longest trace, with no scroll bar.
    void theStepListShowsEveryRowAt1280x800() {
        window_->resize(1280, 800);
        QComboBox* selector = window_->controls()->method_selector();
        selector->setCurrentIndex(selector->findData("xpsm"));
        for (const char* scene : {"data/scenes/box_on_plane.json", "data/scenes/default.json"}) {
            QVERIFY(window_->open_file(source(scene)));
            QVERIFY(settled(*window_));
            QCOMPARE(window_->size(), QSize(1280, 800));
            auto* list = window_->steps()->findChild<QListWidget*>("steps");
            QVERIFY(list && list->count() > 20);
            QVERIFY2(!list->horizontalScrollBar()->isVisible() && !list->verticalScrollBar()->isVisible(), scene);
            for (int row = 0; row < list->count(); ++row)
                QVERIFY2(list->viewport()->rect().contains(list->visualItemRect(list->item(row))),
                         qPrintable(QString("%1: step %2 lies outside the list").arg(scene).arg(row + 1)));
        }
    }

    // The map step's matrix as a 4 x 4 grid of right-aligned columns in a fixed-pitch font, each cell
    // the entry to 4 significant digits; copied, every entry exactly; as the papers print it, the
    // transpose.
    void matricesShowAsAlignedGridsAndCopyAtFullPrecision() {
        const Step& output = window_->inspection()->trace.steps().back();
        QCOMPARE(window_->steps()->chosen(), QString::fromStdString(output.id));
        const auto matrix = std::find_if(output.values.begin(), output.values.end(), [](const NamedValue& v) {
            return std::holds_alternative<glm::dmat4>(v.value);
        });
        QVERIFY(matrix != output.values.end());
        const glm::dmat4 m = std::get<glm::dmat4>(matrix->value);
        const QString name = QString::fromStdString(matrix->name);
        for (const MatrixLayout layout : {MatrixLayout::column_vectors, MatrixLayout::row_vectors}) {
            window_->steps()->set_matrix_layout(layout);
            const glm::dmat4 printed =
                layout == MatrixLayout::column_vectors ? m : glm::transpose(m);  // printed row by row
            const auto* label = window_->steps()->findChild<QLabel*>(name);
            QVERIFY(label && QFontInfo(label->font()).fixedPitch());
            const std::optional<ParsedGrid> shown = parse_grid(label->text().split('\n'));
            QVERIFY2(shown, qPrintable(label->text()));
            for (int r = 0; r < 4; ++r) {
                QCOMPARE(shown->cell_ends[r], shown->cell_ends[0]);
                for (int c = 0; c < 4; ++c) {
                    const double entry = row(printed, r)[c];
                    QVERIFY2(
                        std::abs(shown->cells[r][c] - entry) <= 5e-4 * std::abs(entry),
                        qPrintable(QString("cell %1, %2: %3 for %4").arg(r).arg(c).arg(shown->cells[r][c]).arg(entry)));
                }
            }
            window_->steps()->findChild<QPushButton*>("copyValues")->click();
            const QStringList copied = QApplication::clipboard()->text().split('\n');
            const qsizetype at = copied.indexOf(name + ":");
            QVERIFY(at >= 0);
            const std::optional<ParsedGrid> full = parse_grid(copied.mid(at + 1, 4));
            QVERIFY(full);
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c) QCOMPARE(full->cells[r][c], row(printed, r)[c]);
        }
    }

    // Idle, the Messages dock is one line tall and shows the newest message; an error opens it to a
    // few lines until the next change computes.
    void theMessagesTakeOneLineUntilAnError() {
        auto* messages = window_->findChild<QPlainTextEdit*>("messages");
        const int line = messages->fontMetrics().lineSpacing();
        const auto lines_shown = [messages, line] { return messages->viewport()->height() / line; };
        const auto newest_shows = [this, messages] {
            const QPoint bottom_line(messages->viewport()->width() / 2, messages->viewport()->height() - 6);
            return messages->cursorForPosition(bottom_line).block().text().endsWith(window_->last_message());
        };
        QCOMPARE(lines_shown(), 1);
        QVERIFY(newest_shows());
        QVERIFY(!window_->open_file(source("tests/data/bad/negative_size.json")));
        QVERIFY(settled(*window_));
        QVERIFY(lines_shown() >= 3);
        QVERIFY(newest_shows());
        QVERIFY(window_->open_file(source("data/scenes/box_on_plane.json")));
        QVERIFY(settled(*window_));
        QCOMPARE(lines_shown(), 1);
        QVERIFY(newest_shows());
    }

    // For every map method the window's matrix is the one `shadowlab inspect --json` prints, though
    // the Camera panel's shape is not the scene camera's: the panel letterboxes. Unlocked, the
    // aspect is the panel's, the matrix changes and the status line says where the aspect comes from.
    // An engine's matrices, here the focused map's as OpenGL would hold it, imported from a file and
    // pasted from the clipboard: the window switches to `custom` and reads back the same map; a
    // file of 15 numbers is refused by name and the inspection shown stays.
    void importedAndPastedLightMatricesGiveTheSameMap() {
        QVERIFY(window_->open_file(source("data/scenes/box_on_plane.json")));
        window_->controls()->set_method("focused");
        QVERIFY(settled(*window_));
        const glm::dmat4 focused = window_->inspection()->setup.maps[0].world_to_uvz;
        // As an OpenGL engine holds it: clip space [-1, 1]³, written as GLSL's mat4, column by column.
        const glm::dmat4 clip_from_world = glm::inverse(uvz_from_clip({})) * focused;
        std::ostringstream text;
        text.precision(17);
        text << "uniform mat4 lightViewProjection = mat4(";
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) text << clip_from_world[c][r] << (c == 3 && r == 3 ? ");\n" : ", ");
        const std::string glsl = text.str();
        QTemporaryDir dir;
        const QString file = dir.filePath("engine.glsl");
        std::ofstream(file.toStdString()) << glsl;
        const auto same_map = [&] {
            const glm::dmat4 imported = window_->inspection()->setup.maps[0].world_to_uvz;
            double largest = 0.0;
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) largest = std::max(largest, std::abs(imported[c][r] - focused[c][r]));
            return largest < 1e-9;
        };
        window_->import_light_matrices(file);
        QVERIFY(settled(*window_));
        QCOMPARE(window_->inspection()->name(), std::string("custom"));
        QVERIFY2(same_map(), "imported from a file");
        window_->controls()->set_method("focused");
        QVERIFY(settled(*window_));
        QApplication::clipboard()->setText(QString::fromStdString(glsl));
        window_->paste_light_matrices();
        QVERIFY(settled(*window_));
        QCOMPARE(window_->inspection()->name(), std::string("custom"));
        QVERIFY2(same_map(), "pasted");
        const QString bad = dir.filePath("short.glsl");
        std::ofstream(bad.toStdString()) << "mat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0)";
        window_->import_light_matrices(bad);
        QVERIFY(settled(*window_));
        QVERIFY2(window_->last_message().contains("short.glsl"), qPrintable(window_->last_message()));
        QVERIFY2(same_map(), "the inspection shown stays");
    }

    // An engine's camera written as JSON (OpenGL's conventions) replaces the scene's: the camera
    // computed with is the one written, to 1e-9; a file without a projection is named, the camera stays.
    void anImportedCameraReplacesTheScenes() {
        Camera engine = window_->scene().camera;
        engine.position = {3.0, 4.0, 9.0};
        engine.target = {0.5, 0.0, -1.0};
        engine.fov_y_deg = 40.0;
        engine.near = 0.25, engine.far = 60.0;
        const auto rows = [](const glm::dmat4& m) {
            Json out = Json::array();
            for (int r = 0; r < 4; ++r) out.push_back({m[0][r], m[1][r], m[2][r], m[3][r]});
            return out;
        };
        QTemporaryDir dir;
        const QString file = dir.filePath("camera.json");
        Json root;
        root["camera"] = {{"view", rows(engine.view_matrix())}, {"projection", rows(engine.projection_matrix())}};
        std::ofstream(file.toStdString()) << root.dump();
        window_->import_camera_matrices(file, {});
        QVERIFY(settled(*window_));
        const Camera& used = window_->inspection()->scene.camera;
        QVERIFY2(glm::length(used.position - engine.position) < 1e-9, "the camera's position");
        QVERIFY(glm::length(used.view_direction() - engine.view_direction()) < 1e-9);
        QVERIFY(std::abs(used.fov_y_deg - 40.0) < 1e-9 && std::abs(used.near - 0.25) < 1e-9 &&
                std::abs(used.far - 60.0) < 1e-9);
        const QString bad = dir.filePath("view_only.json");
        std::ofstream(bad.toStdString()) << R"({"camera": {"view": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]}})";
        window_->import_camera_matrices(bad, {});
        QVERIFY(settled(*window_));
        QVERIFY2(window_->last_message().contains("view_only.json"), qPrintable(window_->last_message()));
        QVERIFY(glm::length(window_->scene().camera.position - engine.position) < 1e-9);
    }

    void theWindowsMatricesAreTheClis() {
        window_->resize(1600, 1000);
        const QString scene = source("data/scenes/default.json");
        QVERIFY(window_->open_file(scene));
        QVERIFY(settled(*window_));
        for (const Method& method : all_methods()) {
            if (!method.makes_maps()) continue;
            window_->controls()->set_method(QString::fromStdString(method.name));
            QVERIFY(settled(*window_));
            const InspectionRequest request = window_->controls()->request();
            QCOMPARE(window_->inspection()->name(), method.name);
            try {
                QVERIFY2(window_->inspection()->setup.maps[0].world_to_uvz == cli_world_to_uvz(scene, request),
                         method.name.c_str());  // the CLI prints every double in full: the same bits
            } catch (const std::exception& e) {
                QFAIL(e.what());
            }
            QVERIFY(window_->statusBar()->currentMessage().contains("aspect 1.78 from the scene"));
        }
        const glm::dmat4 locked = window_->inspection()->setup.maps[0].world_to_uvz;
        auto* aspect = window_->controls()->findChild<QComboBox*>("aspect");
        aspect->setCurrentIndex(aspect->findData(false));  // the Camera panel's
        QVERIFY(settled(*window_));
        const QSize panel = panel_showing(view_or_throw("camera"))->drawing_size();
        const double panel_aspect = static_cast<double>(panel.width()) / panel.height();
        QVERIFY2(std::abs(panel_aspect - window_->scene().camera.aspect) > 0.05,
                 "the test needs a panel of another shape");
        QCOMPARE(window_->inspection()->scene.camera.aspect, panel_aspect);
        QVERIFY(window_->inspection()->setup.maps[0].world_to_uvz != locked);
        const QString status = window_->statusBar()->currentMessage();
        const QString said = QString("aspect %1 from the Camera panel").arg(panel_aspect, 0, 'f', 2);
        QVERIFY2(status.contains(said), qPrintable(status));
        window_->resize(1300, 1000);  // the aspect follows the panel once the resize settles
        QTRY_VERIFY(window_->inspection()->scene.camera.aspect != panel_aspect);
        const QSize resized = panel_showing(view_or_throw("camera"))->drawing_size();
        QCOMPARE(window_->inspection()->scene.camera.aspect, static_cast<double>(resized.width()) / resized.height());
    }

    // An orbit the user leaves in the Light space panel survives another step and another method;
    // choosing a preset puts the preset's own camera back.
    void theCameraIsKeptBetweenSteps() {
        QVERIFY(settled(*window_));  // the test before resized the window: its panels redraw first
        ViewPanel* light = panel_showing(view_or_throw("light"));
        const CameraPose placed = CameraPose::of(view_camera(light));
        const auto leave_an_orbit = [light] {  // a drag with the left button: the trackball turns the camera
            auto* widget = light->findChild<QVTKOpenGLNativeWidget*>();
            const QPoint from = widget->rect().center(), to = from + QPoint(60, 30);
            QMouseEvent press(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
            QMouseEvent move(QEvent::MouseMove, to, Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
            QMouseEvent release(QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton, Qt::NoModifier);
            for (QMouseEvent* event : {&press, &move, &release}) QApplication::sendEvent(widget, event);
            return CameraPose::of(view_camera(light));
        };
        const CameraPose left = leave_an_orbit();
        QVERIFY(!same_pose(left, placed));
        const int last = window_->steps()->findChild<QListWidget*>("steps")->count() - 1;
        window_->steps()->choose(1);
        QVERIFY(settled(*window_));
        QVERIFY2(same_pose(CameraPose::of(view_camera(light)), left), "another step moved the camera");
        window_->steps()->choose(last);
        QVERIFY(settled(*window_));
        QVERIFY(same_pose(CameraPose::of(view_camera(light)), left));
        auto* preset = light->findChild<QComboBox*>("presetChooser");
        emit preset->activated(preset->currentIndex());  // the user chooses the preset again
        QVERIFY(settled(*window_));
        // The preset's own view: its focal point, direction and up (its distance fits the panel's
        // shape when built, which the window's layout may have changed since `placed`).
        QVERIFY2(same_direction(CameraPose::of(view_camera(light)), placed),
                 "choosing the preset kept the user's camera");
        const CameraPose left_again = leave_an_orbit();
        QComboBox* selector = window_->controls()->method_selector();
        selector->setCurrentIndex(selector->findData("lispsm"));
        QVERIFY(settled(*window_));
        QVERIFY2(same_pose(CameraPose::of(view_camera(light)), left_again), "another method moved the camera");
    }

    // View > Compare: A (lispsm) and B (focused) side by side. A camera change on either side moves
    // both (the Camera view steers the one scene camera; an orbit of Light space is handed over), B
    // draws A's step index where it has one and its last (with a note) where it has fewer steps, and
    // the Difference view paints where their verdicts differ.
    void compareModeHoldsBothPanelsOnOneCamera() {
        window_->controls()->set_method("lispsm");
        QVERIFY(settled(*window_));
        window_->findChild<QAction*>("compareMode")->trigger();
        window_->compared_controls()->set_method("focused");
        QVERIFY(settled(*window_));
        QVERIFY(window_->comparing());
        const std::vector<ViewPanel*>& panels = window_->panels();
        ViewPanel *a = panels[0], *b = window_->compared_panel();
        QCOMPARE(b, panels[1]);
        QCOMPARE(QString::fromStdString(a->view().name), QString("camera"));
        QCOMPARE(QString::fromStdString(b->view().name), QString("camera"));
        QCOMPARE(QString::fromStdString(panels[2]->view().name), QString("difference"));
        QVERIFY(window_->compared());
        QCOMPARE(QString::fromStdString(window_->inspection()->name()), QString("lispsm"));
        QCOMPARE(QString::fromStdString(window_->compared()->name()), QString("focused"));

        for (ViewPanel* moved : {b, a}) {  // the Camera view dragged on either side
            const glm::dvec3 before = window_->inspection()->scene.camera.position;
            auto* widget = moved->findChild<QVTKOpenGLNativeWidget*>();
            drag(widget, {widget->width() / 2.0, widget->height() / 2.0}, {40, 15});
            QVERIFY(settled(*window_));
            const Camera &camera_a = window_->inspection()->scene.camera, &camera_b = window_->compared()->scene.camera;
            QVERIFY2(glm::length(camera_a.position - before) > 1e-6, "the drag did not move the scene camera");
            QVERIFY(glm::length(camera_a.position - camera_b.position) < 1e-12);
            QVERIFY(glm::length(camera_a.target - camera_b.target) < 1e-12);
            QVERIFY2(same_pose(CameraPose::of(view_camera(a)), CameraPose::of(view_camera(b))),
                     "the two panels do not look through one camera");
        }

        size_t only_one_right = 0;  // the Difference panel: lispsm and focused disagree somewhere
        const RgbImage difference = panels[2]->grab();
        for (size_t i = 0; i < difference.rgb.size(); i += 3)
            for (const difference_colours::Colour& c :
                 {difference_colours::kOnlyARight, difference_colours::kOnlyBRight})
                only_one_right += std::equal(c.begin(), c.end(), &difference.rgb[i]);
        QVERIFY2(only_one_right > 0, "the Difference view paints no pixel where the verdicts differ");

        // Light space in both: an orbit left in one is the other's, and the step index is linked.
        for (ViewPanel* panel : {a, b}) {
            panel->set_view(view_or_throw("light"));
            emit panel->viewChosen();
        }
        QVERIFY(settled(*window_));
        auto* widget = a->findChild<QVTKOpenGLNativeWidget*>();
        drag(widget, {widget->width() / 2.0, widget->height() / 2.0}, {50, 20});
        QVERIFY(settled(*window_));
        QVERIFY2(same_pose(CameraPose::of(view_camera(a)), CameraPose::of(view_camera(b))),
                 "an orbit of A's Light space left B's where it was");
        const std::vector<Step>&steps_a = window_->inspection()->trace.steps(),
              &steps_b = window_->compared()->trace.steps();
        QVERIFY(steps_a.size() > steps_b.size() && steps_b.size() >= 3);
        window_->steps()->choose(2);
        QVERIFY(settled(*window_));
        QCOMPARE(QString::fromStdString(window_->compared_step()), QString::fromStdString(steps_b[2].id));
        window_->steps()->choose(static_cast<int>(steps_a.size()) - 1);
        QVERIFY(settled(*window_));
        QCOMPARE(QString::fromStdString(window_->compared_step()), QString());  // B's last
        QVERIFY2(window_->last_message().contains("has no step"), qPrintable(window_->last_message()));

        window_->findChild<QAction*>("compareMode")->trigger();  // off: the views before, one configuration
        QVERIFY(settled(*window_));
        QVERIFY(!window_->comparing() && !window_->compared());
        QCOMPARE(QString::fromStdString(panels[2]->view().name), QString("light"));
    }

    // View > Before/after warp: Light space beside PPLS in the lower panels, both from the side.
    void beforeAfterWarpShowsLightSpaceAndPplsFromTheSide() {
        window_->findChild<QAction*>("beforeAfterWarp")->trigger();
        QVERIFY(settled(*window_));
        const std::vector<ViewPanel*>& panels = window_->panels();
        QCOMPARE(QString::fromStdString(panels[2]->view().name), QString("light"));
        QCOMPARE(QString::fromStdString(panels[3]->view().name), QString("ppls"));
        for (ViewPanel* panel : {panels[2], panels[3]})
            QCOMPARE(static_cast<int>(panel->preset()), static_cast<int>(SpacePreset::side));
    }

    // "Shadow only" redraws the Camera view as its lit mask.
    void shadowOnlyRedrawsTheCameraView() {
        ViewPanel* camera = panel_showing(view_or_throw("camera"));
        const RgbImage shaded = camera->grab();
        window_->controls()->findChild<QCheckBox*>("shadowOnly")->setChecked(true);
        QVERIFY(settled(*window_));
        QVERIFY2(changed_share(shaded, camera->grab()) > 0.2, "the Camera view did not change to the lit mask");
    }

    // The Camera panel's overlay chooser colours the pixels by the map they read.
    void theCameraOverlayTintsThePicture() {
        ViewPanel* camera = panel_showing(view_or_throw("camera"));
        const RgbImage shadows = camera->grab();
        auto* overlay = camera->findChild<QComboBox*>("overlayChooser");
        QVERIFY(overlay && overlay->isVisibleTo(camera));
        overlay->setCurrentIndex(overlay->findData(static_cast<int>(MapOverlay::cascade_index)));
        emit camera->viewChosen();
        QVERIFY(settled(*window_));
        QVERIFY2(changed_share(shadows, camera->grab()) > 0.2, "the overlay did not tint the Camera view");
        QVERIFY(!panel_showing(view_or_throw("world"))
                     ->findChild<QComboBox*>("overlayChooser")
                     ->isVisibleTo(panel_showing(view_or_throw("world"))));
    }

    // The Plot dock's shimmer is `shadowlab shimmer` with the dock's path and image: the same numbers.
    void thePlotDocksShimmerIsTheCommands() {
        window_->plot()->set_kind(PlotPanel::Kind::shimmer);
        window_->findChild<QDockWidget*>("plotDock")->show();
        QVERIFY(settled(*window_));
        const std::optional<Shimmer>& shimmer = window_->plot()->last_shimmer();
        QVERIFY2(shimmer, "the dock measured no shimmer");
        QVERIFY(shimmer->transitions() > 1000);
        const InspectionRequest request = window_->controls()->request();
        const QTemporaryDir out;
        QProcess cli;
        cli.start(SHADOWLAB_CLI, {"shimmer", source("data/scenes/box_on_plane.json"), "--method",
                                  QString::fromStdString(request.method), "--resolution",
                                  QString::number(request.resolution), "--frames", QString::number(kShimmerFrames),
                                  "--size", QString("%1x%1").arg(kPlotImageWidth), "--out", out.path()});
        QVERIFY(cli.waitForFinished(120000));
        QCOMPARE(cli.exitCode(), 0);
        const QString printed = cli.readAllStandardOutput();
        QVERIFY2(printed.contains(QString::fromStdString(shimmer_summary(*shimmer))),
                 qPrintable("the window: " + QString::fromStdString(shimmer_summary(*shimmer)) +
                            "; the command: " + printed));
    }

    // A glTF file of two cameras opens with its first; choosing the second in the Scene panel reads
    // the file again with it. The roof marked as neither caster nor receiver leaves the casters, and
    // the scene saved as a JSON referencing the file opens with that camera and those roles.
    void aGltfScenesCameraAndRolesAreChosenAndSaved() {
        QTemporaryDir dir;
        const QString gltf = dir.filePath("two_cameras.gltf");
        std::ofstream(gltf.toStdString()) << shadowlab::testing::two_camera_scene().dump();
        QVERIFY(window_->open_file(gltf));
        QVERIFY(settled(*window_));
        const glm::dvec3 first = window_->scene().camera.position;
        auto* camera = window_->scene_panel()->findChild<QComboBox*>("camera");
        QVERIFY(camera && camera->count() == 2);
        camera->setCurrentIndex(1);
        QVERIFY(settled(*window_));
        QVERIFY2(glm::length(window_->inspection()->scene.camera.position - first) > 1.0,
                 "the second camera was not taken");
        const auto roof = std::find_if(window_->scene().objects.begin(), window_->scene().objects.end(),
                                       [](const SceneObject& o) { return o.name == "roof"; });
        QVERIFY(roof != window_->scene().objects.end());
        const int r = static_cast<int>(roof - window_->scene().objects.begin());
        emit window_->scene_panel()->rolesChanged(r, false, false);
        QVERIFY(settled(*window_));
        QVERIFY(!window_->inspection()->casters[r]);
        const QString saved = dir.filePath("chosen.json");
        window_->save_scene(saved);
        const Scene reopened = load_scene(saved.toStdString());
        QVERIFY(glm::length(reopened.camera.position - window_->scene().camera.position) < 1e-9);
        QVERIFY(!reopened.objects[r].casts && !reopened.objects[r].receives);
    }

    void choosingAStepHighlightsItsGeometry() {
        ViewPanel* world = panel_showing(view_or_throw("world"));
        const RgbImage last = world->grab();
        window_->steps()->choose(2);  // the intersection body
        QVERIFY(settled(*window_));
        QCOMPARE(window_->steps()->chosen(), QString("body"));
        QVERIFY2(changed_share(last, world->grab()) > 0.005, "choosing a step did not change the World view");
    }
};

int main(int argc, char** argv) {
    return shadowlab::testing::run_qt_suite<MainWindowTest>(argc, argv, "ShadowLabTests");
}

#include "main_window_test.moc"
