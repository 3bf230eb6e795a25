#pragma once
// Two configurations judged against the same exact reference, pixel by pixel: where both are right,
// where both are wrong, and where only one is (there their verdicts differ, and the reference says
// which is right). Reads the verdicts `measure_shadow_error` or `judge_shadows` gave each
// (ShadowError::verdicts); it judges nothing itself.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "metrics/shadow_error.hpp"

namespace shadowlab {

// A receiver pixel under configurations A and B. A verdict is shadowed or lit, so two wrong verdicts
// are the same verdict: the two differ exactly where one of them is right.
enum class PixelAgreement : uint8_t { none, both_right, both_wrong, only_a_right, only_b_right };

struct VerdictComparison {
    size_t receiver_pixels = 0;  // judged in both (the same pixels: one reference)
    size_t both_right = 0, both_wrong = 0, only_a_right = 0, only_b_right = 0;
    std::vector<PixelAgreement> pixels;  // per pixel of the camera image; none where not judged

    size_t a_wrong() const { return both_wrong + only_b_right; }  // A's misclassified pixels
    size_t b_wrong() const { return both_wrong + only_a_right; }
    size_t differing() const { return only_a_right + only_b_right; }  // where the two verdicts differ
};

// A against B, both judged against one reference (the same image size and receiver pixels: checked).
VerdictComparison compare_verdicts(const ShadowError& a, const ShadowError& b);

}  // namespace shadowlab
