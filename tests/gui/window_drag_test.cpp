// The window while the user drags: a 30-step drag of the light handle over the default scene, a
// step per frame. Every step is computed off the GUI thread and the panels are drawn one per turn
// of the event loop, so a 5 ms heartbeat on the GUI thread never waits more than 50 ms, landings and
// drawings included (issue 16). A ctest of its own, run alone: another test beside it on two cores
// would measure the machine, not the window.
#include <algorithm>
#include <cmath>
#include <QElapsedTimer>
#include <QSettings>
#include <QTimer>
#include <QtTest>

#include "qt_test_main.hpp"
#include "settled.hpp"
#include "gui/main_window.hpp"
#include "gui/view_panel.hpp"

using namespace shadowlab;

class WindowDragTest : public QObject {
    Q_OBJECT

private slots:
    void aLightDragNeverBlocksTheGuiThread() {
        QSettings().clear();
        MainWindow window;
        window.resize(1400, 900);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.open_file(QString(SHADOWLAB_SOURCE_DIR) + "/data/scenes/default.json"));
        QVERIFY(testing::settled(window));
        const auto world = std::find_if(window.panels().begin(), window.panels().end(),
                                        [](ViewPanel* p) { return p->view() == ViewKind::world; });
        QVERIFY(world != window.panels().end());

        QElapsedTimer clock;
        qint64 last_beat = 0, longest_wait = 0;
        QTimer heartbeat;
        heartbeat.setInterval(5);
        connect(&heartbeat, &QTimer::timeout, [&] {
            longest_wait = std::max(longest_wait, clock.elapsed() - last_beat);
            last_beat = clock.elapsed();
        });
        clock.start();
        heartbeat.start();
        constexpr int kSteps = 30;
        glm::dvec3 last_point;
        for (int step = 0; step < kSteps; ++step) {
            const double angle = 0.5 + 0.04 * step;  // the light swings around the town, 60 units out
            last_point = {60.0 * std::cos(angle), 40.0, 60.0 * std::sin(angle)};
            emit(*world)->lightHandleMoved(last_point);
            QTest::qWait(16);
        }
        QVERIFY(testing::settled(window));
        heartbeat.stop();
        qInfo("the GUI thread waited at most %lld ms", static_cast<long long>(longest_wait));
        QVERIFY2(longest_wait <= 50, qPrintable(QString("the GUI thread waited %1 ms").arg(longest_wait)));

        const Aabb bounds = window.scene().bounds();
        const glm::dvec3 towards = glm::normalize(0.5 * (bounds.min + bounds.max) - last_point);
        QVERIFY2(glm::length(window.inspection()->scene.light.direction - towards) < 1e-12,
                 "the last step was not drawn");
    }
};

int main(int argc, char** argv) {
    return shadowlab::testing::run_qt_suite<WindowDragTest>(argc, argv, "ShadowLabDragTests");
}

#include "window_drag_test.moc"
