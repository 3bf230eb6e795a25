#pragma once
// The window's computing, off the GUI thread: one worker thread inspects the newest change and
// prepares what the panels shown will read (depth maps, references, errors: prepare_view), then
// measures the Plot dock's plot, so that the GUI thread only draws. The latest change wins: a newer change cancels an
// older one at the older one's next phase, and only the newest lands. The window reads how far it is for its progress
// line.
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>
#include <QObject>
#include <QString>

#include "gui/plot_measure.hpp"
#include "model/inspection.hpp"
#include "views/view.hpp"

namespace shadowlab {

// A panel the inspection will be drawn in, as it will draw it.
struct ShownView {
    const View* view;
    ViewOptions options;
    bool of_compared = false;  // drawn from the compared configuration (compare mode's B panel)
};

// One change of the window: the scene as it stands (the camera's aspect the one in force), the
// controls' request, the panels shown, the Error view whose error the Diagnosis dock reads if it
// is shown, and the plot if the Plot dock is shown.
struct InspectionJob {
    Scene scene;
    InspectionRequest request;
    // Compare mode: configuration B, inspected on the same scene after the request's (A); every
    // panel's options then name the other configuration (ViewOptions::compared: the Difference view
    // reads it), B for A's panels, A for B's.
    std::optional<InspectionRequest> compared;
    std::vector<ShownView> shown;
    std::optional<ShownView> diagnosis;
    std::optional<PlotRequest> plot;
    std::shared_ptr<const Inspection> before;  // the inspection shown: what a virtual map's page cache keeps
};

// What the worker is doing: a phase's name and how many of the job's phases are done.
struct JobProgress {
    std::string phase;
    int done = 0, total = 0;
};

class BackgroundInspection : public QObject {
    Q_OBJECT
public:
    explicit BackgroundInspection(QObject* parent = nullptr);
    ~BackgroundInspection() override;  // waits for the running phase to end
    BackgroundInspection(const BackgroundInspection&) = delete;
    BackgroundInspection& operator=(const BackgroundInspection&) = delete;

    // Queues the job in place of one not yet started; the running one stops at its next phase.
    void submit(InspectionJob job);
    bool busy() const;  // a job is queued or running: its result has not been delivered yet
    JobProgress progress() const;

signals:
    // Delivered on the GUI thread, for the newest job only: its inspection (and in compare mode B's,
    // else null), then (measured after it
    // landed, as it takes longer) its plot, or why either failed.
    void landed(std::shared_ptr<const Inspection> inspection, std::shared_ptr<const Inspection> compared);
    void plotted(std::shared_ptr<const Plot> plot);
    void failed(const QString& why);

private:
    void work();
    void run(const InspectionJob& job, std::uint64_t number);
    bool superseded(std::uint64_t number) const;
    void deliver(std::uint64_t number, std::function<void()> emit_result);
    void enter_phase(std::string phase, int done, int total);

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<InspectionJob> queued_;
    std::uint64_t newest_ = 0;  // the number of the last job submitted
    bool running_ = false;
    bool stopping_ = false;
    JobProgress progress_;
    std::thread worker_;  // last: it starts once the members it reads exist
};

}  // namespace shadowlab
