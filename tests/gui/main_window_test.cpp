// The window as a user drives it: switching the method changes what the views draw; a bad file
// is reported by name and field while the previous scene stays; a mesh alone becomes a scene.
#include <QCheckBox>
#include <QComboBox>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>

#include "gui/controls_panel.hpp"
#include "gui/main_window.hpp"
#include "gui/step_player.hpp"
#include "gui/view_panel.hpp"

using namespace shadowlab;

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

// An image of the same size filled with its top-left pixel's colour (the background).
RgbImage flat_like(const RgbImage& image) {
    RgbImage flat(image.width, image.height);
    for (size_t i = 0; i < flat.rgb.size(); i += 3) std::copy_n(image.rgb.begin(), 3, flat.rgb.begin() + i);
    return flat;
}

}  // namespace

class MainWindowTest : public QObject {
    Q_OBJECT
    std::unique_ptr<MainWindow> window_;

    ViewPanel* panel_showing(ViewKind view) {
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
        QApplication::processEvents();
    }
    void cleanup() { window_.reset(); }

    void switchingTheMethodChangesTheViews() {
        ViewPanel* light = panel_showing(ViewKind::light);
        ViewPanel* map = panel_showing(ViewKind::shadow_map);
        QVERIFY(light && map);
        const RgbImage light_before = light->grab(), map_before = map->grab();
        QComboBox* selector = window_->controls()->method_selector();
        selector->setCurrentIndex(selector->findData("lispsm"));
        QApplication::processEvents();
        QCOMPARE(QString::fromStdString(window_->inspection()->method->name), QString("lispsm"));
        QVERIFY2(changed_share(light_before, light->grab()) > 0.01, "the Light space view did not change");
        QVERIFY2(changed_share(map_before, map->grab()) > 0.05, "the Shadow map view did not change");
        QVERIFY(window_->steps()->chosen().size() > 0);
    }

    void aBadFileIsReportedAndTheSceneStays() {
        ViewPanel* camera = panel_showing(ViewKind::camera);
        const RgbImage before = camera->grab();
        QVERIFY(!window_->open_file(source("tests/data/bad/negative_size.json")));
        QVERIFY2(window_->last_message().contains("negative_size.json"), qPrintable(window_->last_message()));
        QVERIFY2(window_->last_message().contains("objects[1].size"), qPrintable(window_->last_message()));
        QCOMPARE(QString::fromStdString(window_->scene().name), QString("box_on_plane"));
        QVERIFY(window_->inspection() != nullptr);
        QApplication::processEvents();
        QVERIFY2(changed_share(before, camera->grab()) < 0.001, "the Camera view changed after a failed open");
    }

    void methodAndViewsAreRememberedBetweenRuns() {
        QComboBox* selector = window_->controls()->method_selector();
        selector->setCurrentIndex(selector->findData("lispsm"));
        window_->panels()[0]->set_view(ViewKind::ppls);
        window_->close();  // saves the settings
        MainWindow next;
        QCOMPARE(QString::fromStdString(next.controls()->request().method), QString("lispsm"));
        QCOMPARE(static_cast<int>(next.panels()[0]->view()), static_cast<int>(ViewKind::ppls));
    }

    void aMeshAloneGetsAGroundACameraAndASun() {
        QVERIFY(window_->open_file(source("data/meshes/tetrahedron.obj")));
        QCOMPARE(window_->scene().objects.size(), size_t(2));
        QCOMPARE(QString::fromStdString(window_->scene().name), QString("tetrahedron"));
    }

    void draggingTheLightHandleTurnsTheLight() {
        ViewPanel* world = panel_showing(ViewKind::world);
        ViewPanel* camera = panel_showing(ViewKind::camera);
        const RgbImage before = camera->grab();
        emit world->lightHandleMoved({30.0, 8.0, 0.0});  // dropped low on +x: the light now runs toward -x
        QApplication::processEvents();
        const glm::dvec3 d = window_->scene().light.direction;
        QVERIFY2(d.x < -0.9 && d.y < 0.0, qPrintable(QString("light direction %1 %2 %3").arg(d.x).arg(d.y).arg(d.z)));
        QVERIFY2(changed_share(before, camera->grab()) > 0.01, "the shadows did not move");
    }

    // Volumes draw real stencil shadows in the window's Camera view: with the camera moved into a
    // shadow, z-pass and z-fail give clearly different pictures (z-pass inverts the shadows).
    void volumesDrawStencilShadowsAndTheCameraInShadowBreaksZPass() {
        QVERIFY(window_->open_file(source("data/scenes/volumes.json")));
        QApplication::processEvents();
        ViewPanel* camera = panel_showing(ViewKind::camera);
        const RgbImage map_image = camera->grab();
        const glm::dvec3 outside = window_->scene().camera.position;
        QComboBox* selector = window_->controls()->method_selector();
        selector->setCurrentIndex(selector->findData("volumes"));
        QApplication::processEvents();
        QVERIFY(window_->inspection()->geometry.has_value());
        QVERIFY2(changed_share(map_image, camera->grab()) > 0.0005, "the Camera view did not change for volumes");
        auto* inside = window_->controls()->findChild<QCheckBox*>("cameraInShadow");
        QVERIFY(inside);
        inside->setChecked(true);
        QApplication::processEvents();
        QVERIFY(window_->scene().camera.position != outside);
        const RgbImage zfail = camera->grab();
        auto* count = window_->controls()->findChild<QComboBox*>("count");
        QVERIFY(count);
        count->setCurrentText("zpass");
        QApplication::processEvents();
        const double differ = changed_share(zfail, camera->grab());
        QVERIFY2(differ > 0.2, qPrintable(QString("z-pass and z-fail differ at only %1 of the pixels").arg(differ)));
        inside->setChecked(false);
        QApplication::processEvents();
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
            QApplication::processEvents();
            for (ViewKind view : all_views()) {
                panel->set_view(view);
                emit panel->viewChosen();
                QApplication::processEvents();
                const RgbImage image = panel->grab();
                const double drawn = changed_share(image, flat_like(image));
                QVERIFY2(drawn > 0.01, qPrintable(selector->itemData(m).toString() + " in " + view_title(view) +
                                                  ": the panel is one flat colour"));
            }
        }
    }

    void choosingAStepHighlightsItsGeometry() {
        ViewPanel* world = panel_showing(ViewKind::world);
        const RgbImage last = world->grab();
        window_->steps()->choose(2);  // the intersection body
        QApplication::processEvents();
        QCOMPARE(window_->steps()->chosen(), QString("body"));
        QVERIFY2(changed_share(last, world->grab()) > 0.005, "choosing a step did not change the World view");
    }
};

int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication app(argc, argv);
    QTemporaryDir settings;
    QApplication::setOrganizationName("ShadowLabTests");
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settings.path());
    MainWindowTest test;
    return QTest::qExec(&test, argc, argv);
}

#include "main_window_test.moc"
