#pragma once
// Variance shadow maps (Donnelly and Lauritzen 2006) and exponential variance shadow maps (Lauritzen
// and McCool 2008): a filtered map of depth moments bounds the share of a filter region nearer the
// light than the receiver with Chebyshev's one-tailed inequality.
#include <algorithm>
#include <cmath>
#include <cfloat>

namespace shadowlab {

// The one-tailed Chebyshev bound on the lit share at receiver depth t of a region whose depths have
// mean μ and variance σ²: P(x >= t) <= p_max = σ² / (σ² + (t − μ)²) for t > μ; 1 for t <= μ.
// Seed 001 writes the denominator σ² + (t − μ), without the square: that is not Chebyshev's bound
// (it is not even dimensionally consistent) and lights too much wherever t − μ < 1.
inline double chebyshev_upper_bound(double mean, double variance, double t) {
    if (t <= mean) return 1.0;
    const double d = t - mean;
    return variance / (variance + d * d);
}

// Light bleeding reduction: the bound's tail below `amount` cut to 0 and the rest stretched back over
// [0, 1], linstep(amount, 1, p). A receiver behind two overlapping casters gets a bound of at least
// σ²/(σ² + (t − μ)²) > 0 where it should be dark; the cut darkens those, and sharpens true penumbrae.
inline double reduce_light_bleeding(double p_max, double amount) {
    if (!(amount > 0.0)) return p_max;
    return std::clamp((p_max - amount) / (1.0 - amount), 0.0, 1.0);
}

// EVSM's exponent limit: the second moment of e^{c d}, d in [0, 1], reaches e^{2c}, which a float32
// texel holds only for c <= ln(FLT_MAX) / 2 ≈ 44.36.
inline double evsm_exponent_limit() { return std::log(double(FLT_MAX)) / 2.0; }

// EVSM's two warps of a depth d in [0, 1]: e^{c⁺ d} (its bound tight toward the light) and −e^{−c⁻ d}
// (tight away from it); each is monotonic in d, so the Chebyshev bound holds on the warped depths.
inline double evsm_positive_warp(double depth, double exponent) { return std::exp(exponent * depth); }
inline double evsm_negative_warp(double depth, double exponent) { return -std::exp(-exponent * depth); }

}  // namespace shadowlab
