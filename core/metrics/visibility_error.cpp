#include "metrics/visibility_error.hpp"

#include <cmath>

#include "reference/light_samples.hpp"

namespace shadowlab {
namespace {

bool in_penumbra(double v) { return v > kPenumbraLow && v < 1.0 - kPenumbraLow; }

}  // namespace

double reference_visibility(const ReferenceImage& ref, std::size_t i) {
    return ref.visibility.empty() ? (ref.lit[i] ? 1.0 : 0.0) : double(ref.visibility[i]);
}

VisibilityError visibility_error(const ReferenceImage& ref, std::vector<float> visibility) {
    VisibilityError e;
    e.signed_error.assign(visibility.size(), 0.0f);
    double squared = 0.0, absolute = 0.0, signed_sum = 0.0, noise = 0.0;
    std::size_t judged = 0, shadowed = 0, bleeding = 0, penumbra = 0, reference_penumbra = 0;
    for (std::size_t i = 0; i < visibility.size(); ++i) {
        if (visibility[i] < 0.0f) continue;
        const double truth = reference_visibility(ref, i), error = visibility[i] - truth;
        e.signed_error[i] = float(error);
        ++judged;
        squared += error * error;
        absolute += std::abs(error);
        signed_sum += error;
        if (ref.light_samples > 0) noise += std::pow(visibility_standard_error(truth, ref.light_samples), 2);
        penumbra += in_penumbra(visibility[i]);
        reference_penumbra += in_penumbra(truth);
        if (truth == 0.0) {
            ++shadowed;
            bleeding += visibility[i] > kBleedingThreshold;
        }
    }
    e.image = std::move(visibility);
    if (judged == 0) return e;
    const double n = double(judged);
    e.rmse = std::sqrt(squared / n);
    e.mae = absolute / n;
    e.mean_signed = signed_sum / n;
    e.reference_noise = std::sqrt(noise / n);
    if (reference_penumbra > 0) e.penumbra_width_ratio = double(penumbra) / double(reference_penumbra);
    if (shadowed > 0) e.light_bleeding = double(bleeding) / double(shadowed);
    return e;
}

}  // namespace shadowlab
