// The Diagnosis dock: the causes of the inspection's misclassified pixels, ranked, each with its
// meaning on hover; a remedy applied with one click changes the run (its setting in the Controls
// panel too) and keeps the rest of the window's state, and the cause it treats shrinks.
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QSettings>
#include <QTableWidget>
#include <QtTest>

#include "gui/controls_panel.hpp"
#include "gui/diagnosis_panel.hpp"
#include "gui/main_window.hpp"
#include "qt_test_main.hpp"
#include "settled.hpp"

using namespace shadowlab;

namespace {

std::size_t pixels_of(const Diagnosis& d, PixelCause kind) {
    for (const CauseCount& c : d.causes)
        if (c.kind == kind) return c.pixels;
    return 0;
}

}  // namespace

class DiagnosisPanelTest : public QObject {
    Q_OBJECT
    std::unique_ptr<MainWindow> window_;

    QDoubleSpinBox* bias_slope() { return window_->controls()->findChild<QDoubleSpinBox*>("bias_slope"); }

private slots:
    // psm on the box with no bias at all: acne over the lit faces.
    void init() {
        QSettings().clear();
        window_ = std::make_unique<MainWindow>();
        window_->resize(1400, 900);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
        QVERIFY(window_->open_file(QString(SHADOWLAB_SOURCE_DIR) + "/data/scenes/box_on_plane.json"));
        window_->controls()->set_method("psm");
        QVERIFY(testing::settled(*window_));
        bias_slope()->setValue(0.0);
        emit bias_slope()->editingFinished();
        window_->findChild<QDockWidget*>("diagnosisDock")->show();
        QVERIFY(testing::settled(*window_));
        QCOMPARE(window_->inspection()->settings.number("bias_slope"), 0.0);
    }
    void cleanup() { window_.reset(); }

    void listsTheCausesRankedWithTheirMeaning() {
        const Diagnosis& d = window_->diagnosis()->diagnosis();
        QVERIFY(!d.causes.empty());
        QCOMPARE(d.causes.front().kind, PixelCause::acne);
        auto* table = window_->diagnosis()->findChild<QTableWidget*>("causes");
        size_t listed = 0;  // the causes' rows, each followed by its remedy's button if it has one
        for (int row = 0; row < table->rowCount(); ++row) {
            if (!table->item(row, 0)) continue;
            QVERIFY(listed < d.causes.size());
            const CauseCount& c = d.causes[listed++];
            QCOMPARE(table->item(row, 0)->text(), QString(info(c.kind).name));
            QCOMPARE(table->item(row, 0)->toolTip(), QString::fromUtf8(info(c.kind).meaning));
            QCOMPARE(table->item(row, 1)->text().toULongLong(), static_cast<qulonglong>(c.pixels));
            if (listed > 1) QVERIFY(d.causes[listed - 2].pixels >= c.pixels);
        }
        QCOMPARE(listed, d.causes.size());
    }

    void applyingTheAcneRemedyRaisesTheSlopeBiasAndTheAcneDrops() {
        const std::size_t acne_before = pixels_of(window_->diagnosis()->diagnosis(), PixelCause::acne);
        QVERIFY2(acne_before > 1000, qPrintable(QString::number(acne_before)));
        const glm::dvec3 light = window_->scene().light.direction;
        const int resolution = window_->inspection()->resolution;
        auto* apply = window_->diagnosis()->findChild<QPushButton*>("apply_acne");
        QVERIFY(apply);
        QVERIFY2(apply->text().contains("bias_slope 0 → 1"), qPrintable(apply->text()));
        apply->click();
        QVERIFY(testing::settled(*window_));
        QCOMPARE(bias_slope()->value(), 1.0);
        QCOMPARE(window_->inspection()->settings.number("bias_slope"), 1.0);
        QCOMPARE(QString::fromStdString(window_->inspection()->name()), QString("psm"));  // the rest kept
        QCOMPARE(window_->inspection()->resolution, resolution);
        QVERIFY(window_->scene().light.direction == light);
        const std::size_t acne_after = pixels_of(window_->diagnosis()->diagnosis(), PixelCause::acne);
        QVERIFY2(acne_after * 10 < acne_before,
                 qPrintable(QString("acne %1 → %2 pixels").arg(acne_before).arg(acne_after)));
    }
};

int main(int argc, char** argv) {
    return shadowlab::testing::run_qt_suite<DiagnosisPanelTest>(argc, argv, "ShadowLabDiagnosisTests");
}

#include "diagnosis_panel_test.moc"
