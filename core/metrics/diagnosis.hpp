#pragma once
// "Why is my shadow wrong?": a run's misclassified pixels counted by cause (metrics/pixel_cause.hpp),
// ranked, and for each cause the remedy it implies measured on the same reference: how much of
// that cause it removes and what it adds elsewhere.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "metrics/measurement.hpp"
#include "metrics/pixel_cause.hpp"

namespace shadowlab {

struct RemedyOutcome {
    std::string change;          // Remedy::change
    double removes = 0.0;        // share of the cause's pixels the change sets right
    double adds = 0.0;           // share of the receiver pixels right before and wrong after
    double misclassified = 0.0;  // the run's misclassified share after the change
};

struct CauseCount {
    PixelCause kind = PixelCause::none;
    std::size_t pixels = 0;
    double share = 0.0;  // of the receiver pixels: the causes' shares add up to the run's misclassified
    std::optional<RemedyOutcome> remedy;
};

struct Diagnosis {
    std::size_t misclassified = 0;   // pixels
    std::vector<CauseCount> causes;  // the causes present, most pixels first
};

// The causes of a measured run's pixels (Measurement::error.causes), ranked; no remedy measured.
Diagnosis count_causes(const ShadowError& error);

// The same with each cause's remedy measured: `run` is measure(context, method, settings,
// resolution, bias)'s result. Causes without a remedy (technique, undecided, or one the method
// cannot take) keep none. `on_remedy` hears of each remedy before it is measured (progress).
using RemedyProgress = std::function<void(const CauseInfo& cause, const Remedy& remedy)>;
Diagnosis diagnose(const MeasureContext& context, const Method& method, const Settings& settings, int resolution,
                   double bias, const Measurement& run, const RemedyProgress& on_remedy = {});

}  // namespace shadowlab
