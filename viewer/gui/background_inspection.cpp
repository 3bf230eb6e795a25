#include "gui/background_inspection.hpp"

#include "metrics/page_caching.hpp"

#include <exception>
#include <functional>
#include <utility>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace shadowlab {
namespace {

constexpr int kWorkerNiceness = 10;

}  // namespace

BackgroundInspection::BackgroundInspection(QObject* parent) : QObject(parent), worker_([this] { work(); }) {}

BackgroundInspection::~BackgroundInspection() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
        ++newest_;  // the running job stops at its next phase
    }
    wake_.notify_one();
    worker_.join();
}

void BackgroundInspection::submit(InspectionJob job) {
    {
        const std::lock_guard lock(mutex_);
        queued_ = std::move(job);
        ++newest_;
    }
    wake_.notify_one();
}

bool BackgroundInspection::busy() const {
    const std::lock_guard lock(mutex_);
    return queued_ || running_;
}

JobProgress BackgroundInspection::progress() const {
    const std::lock_guard lock(mutex_);
    return progress_;
}

bool BackgroundInspection::superseded(std::uint64_t number) const {
    const std::lock_guard lock(mutex_);
    return number != newest_;
}

void BackgroundInspection::enter_phase(std::string phase, int done, int total) {
    const std::lock_guard lock(mutex_);
    progress_ = {std::move(phase), done, total};
}

void BackgroundInspection::work() {
    // Below the GUI thread: on a machine of few cores the worker (and the threads it starts, which
    // inherit its niceness) yields to drawing and input. Linux keeps a niceness per thread.
    setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), kWorkerNiceness);
    for (;;) {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [this] { return stopping_ || queued_; });
        if (stopping_) return;
        const InspectionJob job = std::move(*std::exchange(queued_, std::nullopt));
        const std::uint64_t number = newest_;
        running_ = true;
        lock.unlock();
        run(job, number);
        lock.lock();
        running_ = false;  // after the delivery is posted: busy() turns false with the result on its way
    }
}

// On the GUI thread, unless a newer job came before it got there.
void BackgroundInspection::deliver(std::uint64_t number, std::function<void()> emit_result) {
    QMetaObject::invokeMethod(
        this,
        [this, number, emit_result] {
            if (!superseded(number)) emit_result();
        },
        Qt::QueuedConnection);
}

// The phases: the method (inspect_scene), then each panel's lazy parts and the diagnosis's error,
// then the plot. Between two, a newer job cancels this one; a result is posted to the GUI thread
// only if none came.
void BackgroundInspection::run(const InspectionJob& job, std::uint64_t number) {
    std::vector<std::pair<std::string, const ShownView*>> prepared;
    for (const ShownView& shown : job.shown)
        prepared.emplace_back("preparing the " + shown.view->title + " view", &shown);
    if (job.diagnosis) prepared.emplace_back("diagnosing the misclassified pixels", &*job.diagnosis);
    const int computed_first = job.compared ? 2 : 1;
    const int phases = computed_first + static_cast<int>(prepared.size()) + (job.plot ? 1 : 0);
    try {
        enter_phase("computing " + job.request.method, 0, phases);
        Inspection computed = inspect_scene(job.scene, job.request);
        computed.pages_kept = kept_maps(job.before ? &job.before->setup : nullptr, computed.setup);
        auto inspection = std::make_shared<const Inspection>(std::move(computed));
        std::shared_ptr<const Inspection> compared;
        if (job.compared) {
            if (superseded(number)) return;
            enter_phase("computing B: " + job.compared->method, 1, phases);
            compared = std::make_shared<const Inspection>(inspect_scene(job.scene, *job.compared));
        }
        for (size_t i = 0; i < prepared.size(); ++i) {
            if (superseded(number)) return;
            enter_phase(prepared[i].first, computed_first + static_cast<int>(i), phases);
            const ShownView& shown = *prepared[i].second;
            const bool of_b = shown.of_compared && compared;
            ViewOptions options = shown.options;
            options.compared = of_b ? inspection : compared;  // the other configuration
            prepare_view(of_b ? *compared : *inspection, *shown.view, options);
        }
        deliver(number, [this, inspection, compared] { emit landed(inspection, compared); });
        if (!job.plot || superseded(number)) return;
        enter_phase(plot_work(*job.plot), phases - 1, phases);
        auto plot = std::make_shared<const Plot>(measure_plot(*job.plot));
        deliver(number, [this, plot] { emit plotted(plot); });
    } catch (const std::exception& e) {
        deliver(number, [this, why = QString::fromStdString(e.what())] { emit failed(why); });
    }
}

}  // namespace shadowlab
