#pragma once
// What every filter of prefiltered moments (vsm, evsm, msm, esm) reads the same way: no taps of the
// depth texture, one bilinear read of the blurred moments (four texels) at the receiver's (u, v).
#include <algorithm>
#include <cmath>
#include <vector>

#include "lookup/moment_map.hpp"
#include "lookup/shadow_reader.hpp"

namespace shadowlab {

inline std::vector<KernelTap> no_taps(const ShadowFilter&) { return {}; }
inline int bilinear_reads(const ShadowFilter&) { return 4; }

// A depth distribution's mean and standard deviation from its first two moments, √(m₂ − m₁²).
inline glm::dvec2 mean_and_deviation(double first, double second) {
    return {first, std::sqrt(std::max(0.0, second - first * first))};
}

// The blurred moments at the receiver, counted as four texel reads.
inline glm::dvec4 moments_at(const ShadowReader& reader, const MapReceiver& m, LookupCount* count) {
    if (count) count->taps += 4;
    return sample_moments(*reader.moments(), m.map, m.uv);
}

}  // namespace shadowlab
