#include "metrics/diagnosis.hpp"

#include <algorithm>

namespace shadowlab {
namespace {

bool wrong(PixelVerdict v) { return v == PixelVerdict::false_shadow || v == PixelVerdict::false_light; }

// The remedy's run held against the diagnosed one, pixel by pixel.
RemedyOutcome outcome(const Remedy& remedy, PixelCause cause, const ShadowError& before, const ShadowError& after) {
    std::size_t of_cause = 0, removed = 0, added = 0;
    for (std::size_t i = 0; i < before.verdicts.size(); ++i) {
        if (before.causes[i] == cause) {
            ++of_cause;
            removed += after.verdicts[i] == PixelVerdict::agree;
        }
        added += before.verdicts[i] == PixelVerdict::agree && wrong(after.verdicts[i]);
    }
    return {.change = remedy.change,
            .removes = of_cause ? double(removed) / double(of_cause) : 0.0,
            .adds = before.receiver_pixels ? double(added) / double(before.receiver_pixels) : 0.0,
            .misclassified = after.misclassified};
}

}  // namespace

Diagnosis count_causes(const ShadowError& error) {
    Diagnosis d;
    for (const CauseInfo& cause : all_causes()) {
        const auto pixels = std::size_t(std::count(error.causes.begin(), error.causes.end(), cause.kind));
        if (pixels == 0) continue;
        d.misclassified += pixels;
        d.causes.push_back({.kind = cause.kind,
                            .pixels = pixels,
                            .share = double(pixels) / double(std::max<std::size_t>(error.receiver_pixels, 1))});
    }
    std::stable_sort(d.causes.begin(), d.causes.end(),
                     [](const CauseCount& a, const CauseCount& b) { return a.pixels > b.pixels; });
    return d;
}

Diagnosis diagnose(const MeasureContext& context, const Method& method, const Settings& settings, int resolution,
                   double bias, const Measurement& run, const RemedyProgress& on_remedy) {
    Diagnosis d = count_causes(run.error);
    const RemedyInputs inputs{.method = method,
                              .settings = settings,
                              .resolution = resolution,
                              .bias = bias,
                              .m_perspective_p95 = run.error.m_perspective.p95,
                              .m_p95 = run.error.m.p95};
    for (CauseCount& cause : d.causes) {
        const CauseInfo& c = info(cause.kind);
        if (!c.remedy) continue;
        const std::optional<Remedy> remedy = c.remedy(inputs);
        if (!remedy) continue;
        if (on_remedy) on_remedy(c, *remedy);
        const Measurement after = measure(context, *remedy->method, remedy->settings, remedy->resolution, remedy->bias);
        cause.remedy = outcome(*remedy, cause.kind, run.error, after.error);
    }
    return d;
}

}  // namespace shadowlab
