// Issue 25's promise for views: a view registered by a test binary (not shipped) goes through
// `shadowlab render --view` and the window with no other edit. The render command draws it and
// names it among the known views; a panel of the window lists it, shows the choosers it names,
// has its prepare step run on the worker thread, and draws it.
#include <atomic>
#include <stdexcept>
#include <QComboBox>
#include <QtTest>
#include <vtkRenderer.h>

#include "qt_test_main.hpp"
#include "render_command.hpp"
#include "settled.hpp"
#include "gui/main_window.hpp"
#include "gui/view_panel.hpp"
#include "scene/scene_loader.hpp"
#include "views/view_parts.hpp"

using namespace shadowlab;
using shadowlab::testing::settled;

namespace {

constexpr std::array<unsigned char, 3> kCovered{230, 40, 200}, kClear{0, 0, 0};

std::atomic<int> prepared{0};

// The throw-away view: the shadow map's coverage, a texel magenta where a caster is drawn into
// it, black where it is clear, over a grey backdrop.
RgbImage coverage_image(const DepthMap& depth) {
    RgbImage image(depth.resolution, depth.resolution);
    for (int y = 0; y < depth.resolution; ++y)
        for (int x = 0; x < depth.resolution; ++x) {
            const auto& colour = depth.at(x, y) < 1.0f ? kCovered : kClear;
            std::copy(colour.begin(), colour.end(), image.at(x, depth.resolution - 1 - y));  // v up
        }
    return image;
}

ViewReport build_coverage(vtkRenderer* renderer, const Inspection& in, const ViewOptions&) {
    renderer->SetBackground(0.5, 0.5, 0.5);
    if (in.has_map()) show_image(renderer, coverage_image(in.depth()));
    return {};
}

void register_coverage_view() {
    if (find_view("coverage")) return;
    register_view({.name = "coverage",
                   .title = "Coverage",
                   .prepare =
                       [](const Inspection& in, const ViewOptions&) {
                           ++prepared;
                           if (in.has_map()) in.depth();
                       },
                   .build = build_coverage,
                   .choosers = {.preset = true},
                   .interaction = {.drag = ViewDrag::pans_image}});
}

// The share of a map's texels a caster is drawn into.
double covered_share(const DepthMap& depth) {
    size_t covered = 0;
    for (int y = 0; y < depth.resolution; ++y)
        for (int x = 0; x < depth.resolution; ++x) covered += depth.at(x, y) < 1.0;
    return static_cast<double>(covered) / depth.codes.size();
}

// The share of the picture's magenta among its magenta and black pixels (the backdrop left out),
// and how many pixels those are.
struct Picture {
    double covered_share = 0.0;
    size_t counted = 0;
};

Picture picture_of(const RgbImage& image) {
    size_t covered = 0, clear = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const unsigned char* c = image.at(x, y);
            covered += std::equal(kCovered.begin(), kCovered.end(), c);
            clear += std::equal(kClear.begin(), kClear.end(), c);
        }
    return {.covered_share = static_cast<double>(covered) / std::max<size_t>(1, covered + clear),
            .counted = covered + clear};
}

QString scene_file() { return QString(SHADOWLAB_SOURCE_DIR) + "/data/scenes/box_on_plane.json"; }

}  // namespace

class ViewExtensionTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { register_coverage_view(); }

    void theRenderCommandDrawsAThrowAwayView() {
        const QString out = QDir::temp().filePath("shadowlab_coverage_view.png");
        QFile::remove(out);
        run_render({.scene_file = scene_file().toStdString(),
                    .method = "focused",
                    .view = "coverage",
                    .width = 256,
                    .height = 256,
                    .resolution = 256,
                    .out = out.toStdString()});
        const Picture drawn = picture_of(read_png(out.toStdString()));
        const Inspection in = inspect_scene(load_scene(scene_file().toStdString()), {.resolution = 256});
        const double expected = covered_share(in.depth());
        QVERIFY2(expected > 0.01 && expected < 0.99, qPrintable(QString("covered share %1").arg(expected)));
        QVERIFY2(drawn.counted > 256 * 256 / 2, qPrintable(QString("%1 pixels of the map").arg(drawn.counted)));
        QVERIFY2(std::abs(drawn.covered_share - expected) < 0.02,
                 qPrintable(QString("drawn %1, the map's %2").arg(drawn.covered_share).arg(expected)));
    }

    void anUnknownViewIsANamedErrorListingTheRegisteredOnes() {
        try {
            run_render({.scene_file = scene_file().toStdString(), .view = "sideways", .out = "unused.png"});
            QFAIL("an unknown view was drawn");
        } catch (const std::invalid_argument& e) {
            const QString what = e.what();
            QVERIFY2(what.contains("unknown view 'sideways'") && what.contains("coverage"), qPrintable(what));
        }
    }

    void aPanelListsPreparesAndDrawsAThrowAwayView() {
        QSettings().clear();
        MainWindow window;
        window.resize(1400, 900);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.open_file(scene_file()));
        QVERIFY(settled(window));
        ViewPanel* panel = window.panels().at(0);
        QVERIFY(panel->findChild<QComboBox*>("viewChooser")->findData("coverage") >= 0);

        const int prepared_before = prepared;
        panel->set_view(view_or_throw("coverage"));
        emit panel->viewChosen();
        QVERIFY(settled(window));
        QVERIFY2(prepared > prepared_before, "the view's prepare step did not run");
        QVERIFY(panel->findChild<QComboBox*>("presetChooser")->isVisibleTo(panel));
        QVERIFY(!panel->findChild<QComboBox*>("errorChooser")->isVisibleTo(panel));
        QVERIFY(!panel->findChild<QComboBox*>("overlayChooser")->isVisibleTo(panel));

        const Picture drawn = picture_of(panel->grab());
        const double expected = covered_share(window.inspection()->depth());
        QVERIFY2(drawn.counted > 10000, qPrintable(QString("%1 pixels of the map").arg(drawn.counted)));
        QVERIFY2(std::abs(drawn.covered_share - expected) < 0.03,
                 qPrintable(QString("drawn %1, the map's %2").arg(drawn.covered_share).arg(expected)));
    }
};

int main(int argc, char** argv) {
    return shadowlab::testing::run_qt_suite<ViewExtensionTest>(argc, argv, "ShadowLabViewExtensionTest");
}

#include "view_extension_test.moc"
