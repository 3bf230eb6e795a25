#pragma once
// Exponential shadow maps (Annen, Mertens, Seidel, Flerackers and Kautz, "Exponential Shadow Maps",
// GI 2008): the step s(d) = [d <= z] approximated by e^{−c (d − z)} = e^{c z} e^{−c d}, which
// separates, so that blurring e^{c z} over the filter region filters the shadow test itself.
#include <algorithm>
#include <cfloat>
#include <cmath>

namespace shadowlab {

// The exponent's limit: e^{c z}, z in [0, 1], reaches e^{c}, which a float32 texel holds only for
// c <= ln(FLT_MAX) ≈ 88.72.
inline double esm_exponent_limit() { return std::log(double(FLT_MAX)); }

// The visibility at receiver depth d from the blurred E[e^{c z}]: E[e^{c z}] e^{−c d}, which is
// more than 1 (clamped: lit) in front of the casters and falls as e^{−c Δ} behind them.
inline double esm_visibility(double mean_exponential, double depth, double exponent) {
    return std::clamp(mean_exponential * std::exp(-exponent * depth), 0.0, 1.0);
}

}  // namespace shadowlab
