#pragma once
// Normalising an input vector of any finite size. glm::normalize squares the components, so
// (1e308, -1e308, 0) overflows to inf and 1e-200 underflows to 0: either way NaN comes out.
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace shadowlab {

// The unit vector along v, for any finite non-zero v: divided by its largest |component| first,
// the squares summed lie in [1, 3]. A zero or non-finite v has no direction: callers check their
// input first (the scene loader refuses such vectors by name).
inline glm::dvec3 normalize_safely(const glm::dvec3& v) {
    const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    return glm::normalize(v / largest);
}

}  // namespace shadowlab
