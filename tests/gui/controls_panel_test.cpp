// The method settings as the Controls panel lays them out: a map method's own settings, then its
// lookup's under a Filter header, only what the chosen filter reads, and a Depth bias header; the request
// leaves out what the filter does not read. And in the window a bad value is still refused by the
// setting's name, the last inspection kept.
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>

#include "qt_test_main.hpp"
#include "settled.hpp"
#include "gui/controls_panel.hpp"
#include "gui/main_window.hpp"

using namespace shadowlab;

namespace {

const QStringList kPcfSettings{"pcf_kernel", "kernel_size", "filter_radius", "filter_world_radius"};
const QStringList kMomentSettings{"min_variance", "bleed_reduction"};
const QStringList kEvsmSettings{"evsm_positive", "evsm_negative"};
const QStringList kBiasSettings{"bias_constant",  "bias_slope",    "bias_normal",      "bias_receiver_plane",
                                "contact_length", "contact_steps", "contact_thickness"};

}  // namespace

class ControlsPanelTest : public QObject {
    Q_OBJECT
    std::unique_ptr<ControlsPanel> controls_;

    QWidget* editor(const QString& name) { return controls_->findChild<QWidget*>(name); }
    bool shown(const QString& name) { return editor(name) && editor(name)->isVisibleTo(controls_.get()); }
    void choose_filter(const QString& filter) {
        controls_->findChild<QComboBox*>("filter")->setCurrentText(filter);
        QApplication::processEvents();  // the form lays out its rows again
    }
    bool requested(const QString& name) { return controls_->request().settings.count(name.toStdString()) > 0; }

private slots:
    void init() {
        controls_ = std::make_unique<ControlsPanel>();
        controls_->set_method("lispsm");
        controls_->show();
    }
    void cleanup() { controls_.reset(); }

    void theMethodsOwnSettingsComeFirstThenFilterThenBias() {
        choose_filter("pcf");
        QWidget* filter = controls_->findChild<QLabel*>("filterSettings");
        QWidget* bias = controls_->findChild<QLabel*>("biasSettings");
        QVERIFY(filter && bias);
        const auto top = [&](QWidget* w) { return w->mapTo(controls_.get(), QPoint(0, 0)).y(); };
        QVERIFY(top(editor("eta")) < top(filter));
        for (const QString& name : kPcfSettings + QStringList{"filter"})
            QVERIFY2(top(filter) < top(editor(name)) && top(editor(name)) < top(bias), qPrintable(name));
        for (const QString& name : kBiasSettings) QVERIFY2(top(bias) < top(editor(name)), qPrintable(name));
    }

    void aHardLookupShowsNoFilterSettingsAndPcfShowsItsOwn() {
        choose_filter("hard");
        for (const QString& name : kPcfSettings + kMomentSettings + kEvsmSettings) {
            QVERIFY2(!shown(name), qPrintable(name + " shown under filter=hard"));
            QVERIFY2(!requested(name), qPrintable(name + " requested under filter=hard"));
        }
        for (const QString& name : kBiasSettings) QVERIFY2(shown(name), qPrintable(name));
        choose_filter("pcf");
        for (const QString& name : kPcfSettings) {
            QVERIFY2(shown(name), qPrintable(name + " hidden under filter=pcf"));
            QVERIFY2(requested(name), qPrintable(name + " not requested under filter=pcf"));
        }
        for (const QString& name : kMomentSettings + kEvsmSettings) QVERIFY2(!shown(name), qPrintable(name));
    }

    void evsmShowsTheMomentsSettingsAndItsExponents() {
        choose_filter("vsm");
        for (const QString& name : kMomentSettings + QStringList{"kernel_size"})
            QVERIFY2(shown(name), qPrintable(name));
        for (const QString& name : kEvsmSettings + QStringList{"pcf_kernel", "filter_radius"})
            QVERIFY2(!shown(name), qPrintable(name));
        choose_filter("evsm");
        for (const QString& name : kMomentSettings + kEvsmSettings) QVERIFY2(shown(name), qPrintable(name));
        choose_filter("pcss");
        QVERIFY(shown("kernel_size"));
        for (const QString& name : kMomentSettings + QStringList{"pcf_kernel"})
            QVERIFY2(!shown(name), qPrintable(name));
    }

    void aTechniqueHasNoFilterOrBiasGroup() {
        controls_->set_method("volumes");
        QVERIFY(!editor("filter"));
        QVERIFY(!editor("bias_slope"));
    }

    // Half a tap is no kernel: the window names the setting and keeps the inspection it had.
    void aBadValueIsRefusedByName() {
        QSettings().clear();
        MainWindow window;
        window.resize(1200, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.open_file(QString(SHADOWLAB_SOURCE_DIR) + "/data/scenes/box_on_plane.json"));
        window.controls()->findChild<QComboBox*>("filter")->setCurrentText("pcf");
        QVERIFY(testing::settled(window));
        QCOMPARE(QString::fromStdString(window.inspection()->lookup.filter.kind), QString("pcf"));
        auto* kernel = window.controls()->findChild<QDoubleSpinBox*>("kernel_size");
        kernel->setValue(2.5);
        emit kernel->editingFinished();
        QVERIFY(testing::settled(window));
        QVERIFY2(window.last_message().contains("kernel_size"), qPrintable(window.last_message()));
        QCOMPARE(window.inspection()->lookup.filter.kernel_size, 3);
    }
};

int main(int argc, char** argv) {
    return shadowlab::testing::run_qt_suite<ControlsPanelTest>(argc, argv, "ShadowLabControlsTests");
}

#include "controls_panel_test.moc"
