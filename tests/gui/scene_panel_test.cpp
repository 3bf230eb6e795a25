// The Scene panel: it lists the scene's objects with their roles, a toggled checkbox asks for the
// object's new roles, and for a glTF scene it offers the file's cameras and lights, the chosen ones
// current, a choice asking for that camera or light.
#include <QComboBox>
#include <QSignalSpy>
#include <QTableWidget>
#include <QtTest>

#include "qt_test_main.hpp"
#include "gui/scene_panel.hpp"

using namespace shadowlab;

namespace {

// A ground that receives only and a roof that does both; two cameras and one sun, the second camera chosen.
Scene two_object_scene() {
    Scene scene;
    scene.objects.resize(2);
    scene.objects[0].name = "ground";
    scene.objects[0].casts = false;
    scene.objects[1].name = "roof";
    return scene;
}
const GltfContents kTwoCamerasOneSun{.cameras = {{"main camera", "perspective"}, {"side camera", "perspective"}},
                                     .lights = {{"sun", "directional"}}};
constexpr SceneChoice kSecondCamera{.camera = 1, .light = 0};

}  // namespace

class ScenePanelTest : public QObject {
    Q_OBJECT
    std::unique_ptr<ScenePanel> panel_;

    QTableWidget* objects() { return panel_->findChild<QTableWidget*>("objects"); }
    QComboBox* combo(const char* name) { return panel_->findChild<QComboBox*>(name); }
    bool checked(int row, int column) { return objects()->item(row, column)->checkState() == Qt::Checked; }

private slots:
    void init() {
        panel_ = std::make_unique<ScenePanel>();
        panel_->show();
    }
    void cleanup() { panel_.reset(); }

    void listsEachObjectWithItsRoles() {
        const Scene scene = two_object_scene();
        panel_->set_scene(scene);
        QCOMPARE(objects()->rowCount(), int(scene.objects.size()));
        for (int row = 0; row < objects()->rowCount(); ++row) {
            const SceneObject& object = scene.objects[std::size_t(row)];
            QCOMPARE(objects()->item(row, 0)->text(), QString::fromStdString(object.name));
            QCOMPARE(checked(row, 1), object.casts);
            QCOMPARE(checked(row, 2), object.receives);
        }
        QVERIFY(!combo("camera")->isVisibleTo(panel_.get()));  // a scene of its own: nothing to choose
    }

    void togglingACheckboxAsksForThatObjectsNewRoles() {
        panel_->set_scene(two_object_scene());
        QSignalSpy roles(panel_.get(), &ScenePanel::rolesChanged);
        objects()->item(1, 2)->setCheckState(Qt::Unchecked);  // the roof no longer receives
        QCOMPARE(roles.count(), 1);
        QCOMPARE(roles.at(0), (QVariantList{1, true, false}));
        objects()->item(0, 1)->setCheckState(Qt::Checked);  // the ground casts too
        QCOMPARE(roles.count(), 2);
        QCOMPARE(roles.at(1), (QVariantList{0, true, true}));
    }

    void settingTheSceneAsksForNothing() {
        QSignalSpy roles(panel_.get(), &ScenePanel::rolesChanged);
        QSignalSpy cameras(panel_.get(), &ScenePanel::cameraChosen);
        panel_->set_scene(two_object_scene(), &kTwoCamerasOneSun, kSecondCamera);
        panel_->set_scene(two_object_scene(), &kTwoCamerasOneSun, {});
        QCOMPARE(roles.count(), 0);
        QCOMPARE(cameras.count(), 0);
    }

    void aGltfSceneOffersTheFilesCamerasAndLightsTheChosenCurrent() {
        panel_->set_scene(two_object_scene(), &kTwoCamerasOneSun, kSecondCamera);
        QComboBox* camera = combo("camera");
        QVERIFY(camera->isVisibleTo(panel_.get()));
        QCOMPARE(camera->count(), int(kTwoCamerasOneSun.cameras.size()));
        QCOMPARE(camera->currentIndex(), int(kSecondCamera.camera));
        QVERIFY(camera->currentText().contains("side camera"));
        QCOMPARE(combo("light")->count(), int(kTwoCamerasOneSun.lights.size()));
        QVERIFY(!combo("light")->isEnabled());  // one light: nothing to choose

        QSignalSpy cameras(panel_.get(), &ScenePanel::cameraChosen);
        camera->setCurrentIndex(0);
        QCOMPARE(cameras.count(), 1);
        QCOMPARE(cameras.at(0).at(0).toInt(), 0);
    }
};

int main(int argc, char** argv) {
    return shadowlab::testing::run_qt_suite<ScenePanelTest>(argc, argv, "ShadowLabScenePanelTests");
}

#include "scene_panel_test.moc"
