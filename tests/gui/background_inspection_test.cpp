// The window's worker: of changes made faster than they compute, only the newest lands (the older
// ones cancelled or dropped), with what its panels read prepared; a change that cannot be inspected
// is told, with the reason, and lands nothing.
#include <QtTest>

#include "qt_test_main.hpp"
#include "gui/background_inspection.hpp"
#include "scene/scene_loader.hpp"

using namespace shadowlab;

namespace {

// What a worker delivered, in order ("landed", "plotted", "failed").
struct Delivered {
    std::vector<std::shared_ptr<const Inspection>> landed;
    std::vector<std::shared_ptr<const Plot>> plotted;
    QStringList failed, order;

    explicit Delivered(BackgroundInspection& worker) {
        QObject::connect(&worker, &BackgroundInspection::landed, [this](std::shared_ptr<const Inspection> in) {
            landed.push_back(std::move(in));
            order << "landed";
        });
        QObject::connect(&worker, &BackgroundInspection::plotted, [this](std::shared_ptr<const Plot> plot) {
            plotted.push_back(std::move(plot));
            order << "plotted";
        });
        QObject::connect(&worker, &BackgroundInspection::failed, [this](const QString& why) {
            failed << why;
            order << "failed";
        });
    }
};

InspectionJob job_for(const Scene& scene, const std::string& method) {
    InspectionJob job{
        .scene = scene, .request = {}, .shown = {{&view_or_throw("shadowmap"), {}}, {&view_or_throw("world"), {}}}};
    job.request.method = method;
    job.request.resolution = 512;
    return job;
}

}  // namespace

class BackgroundInspectionTest : public QObject {
    Q_OBJECT
    const Scene scene_ = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/default.json");

private slots:
    void ofThreeQuickChangesOnlyTheNewestLands() {
        BackgroundInspection worker;
        const Delivered delivered(worker);
        for (const char* method : {"lispsm", "psm", "tsm"}) worker.submit(job_for(scene_, method));
        QVERIFY(worker.busy());
        QTRY_VERIFY_WITH_TIMEOUT(!worker.busy(), 60000);
        QApplication::processEvents();  // the delivery, posted before busy() turned false
        QCOMPARE(delivered.landed.size(), size_t(1));
        QVERIFY(delivered.failed.isEmpty());
        QCOMPARE(delivered.landed.front()->name(), std::string("tsm"));
        QCOMPARE(delivered.landed.front()->depth().resolution, 512);  // prepared for the Shadow map view
    }

    // The plot, slower than the inspection, lands after it: the views do not wait for the Plot dock.
    void thePlotLandsAfterTheInspection() {
        BackgroundInspection worker;
        const Delivered delivered(worker);
        InspectionJob job = job_for(scene_, "lispsm");
        job.plot = PlotRequest{.kind = PlotKind::error_against_resolution,
                               .scene = scene_,
                               .method = "lispsm",
                               .settings = {},
                               .resolution = 512};
        worker.submit(std::move(job));
        QTRY_VERIFY_WITH_TIMEOUT(!worker.busy(), 120000);
        QApplication::processEvents();
        QCOMPARE(delivered.order, QStringList({"landed", "plotted"}));
        const ChartSpec& chart = delivered.plotted.front()->chart;
        QCOMPARE(chart.series.size(), size_t(2));
        QCOMPARE(chart.series.front().x, std::vector<double>({256, 512, 1024, 2048}));
    }

    void aChangeThatCannotBeInspectedIsToldWhy() {
        BackgroundInspection worker;
        const Delivered delivered(worker);
        worker.submit(job_for(scene_, "no_such_method"));
        QTRY_VERIFY_WITH_TIMEOUT(!worker.busy(), 60000);
        QApplication::processEvents();
        QVERIFY(delivered.landed.empty());
        QCOMPARE(delivered.failed.size(), 1);
        QVERIFY2(delivered.failed.front().contains("no_such_method"), qPrintable(delivered.failed.front()));
    }
};

int main(int argc, char** argv) {
    return shadowlab::testing::run_qt_suite<BackgroundInspectionTest>(argc, argv, "ShadowLabWorkerTests");
}

#include "background_inspection_test.moc"
