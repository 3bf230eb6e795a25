#pragma once
// How far a method's visibility (0 shadowed .. 1 lit, filtered or not) lies from the reference's:
// the soft reference's share of an area light, or the hard reference's 0 or 1 when the light has no
// size. Judged on the receiver pixels, beside the reference's own Monte Carlo noise.
#include <optional>
#include <vector>

#include "reference/exact_shadows.hpp"

namespace shadowlab {

// Visibility strictly inside (kPenumbraLow, 1 − kPenumbraLow) counts as penumbra: above one light
// sample of 64 at either end, so that the reference's single-ray tails are not counted as width.
constexpr double kPenumbraLow = 0.02;
// A fully shadowed reference pixel bleeds when the method lights it above this.
constexpr double kBleedingThreshold = 0.1;

struct VisibilityError {
    double rmse = 0.0, mae = 0.0;  // over the judged pixels
    double mean_signed = 0.0;      // method − reference: > 0 lights too much, < 0 darkens too much
    // The reference's own error: the RMS over the judged pixels of its standard error, √(v (1 − v) / N)
    // (0 for a hard reference). A method closer than this cannot be told from exact.
    double reference_noise = 0.0;
    // The penumbra's mean width along the shadow edges, the method's over the reference's: both
    // images share the edges' length, so the ratio of penumbra pixels is the ratio of widths (1:
    // exact; 0: hard edges). None where the reference has no penumbra.
    std::optional<double> penumbra_width_ratio;
    double light_bleeding = 0.0;      // share of the fully shadowed reference pixels lit above kBleedingThreshold
    std::vector<float> image;         // the method's visibility per pixel; -1 where not judged
    std::vector<float> signed_error;  // method − reference per judged pixel; 0 elsewhere
};

// The reference's visibility at pixel i: the soft share where traced, else lit as 0 or 1.
double reference_visibility(const ReferenceImage& reference, std::size_t i);

// `visibility`: the method's per pixel of the reference's image, -1 where not judged.
VisibilityError visibility_error(const ReferenceImage& reference, std::vector<float> visibility);

}  // namespace shadowlab
