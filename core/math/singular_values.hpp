#pragma once
// The smallest singular value of a 2x2 matrix, from its Frobenius norm and determinant: how far a
// Jacobian shrinks the direction it shrinks most (a texel's longest extent is 1 / σ_min of (u, v)'s
// Jacobian). No iteration, no square root of a negative: the discriminant is clamped at 0.
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace shadowlab {

inline double smallest_singular_value(const glm::dmat2& j) {
    const double f = glm::dot(j[0], j[0]) + glm::dot(j[1], j[1]), det = std::abs(glm::determinant(j));
    return std::sqrt(std::max(0.0, (f - std::sqrt(std::max(0.0, f * f - 4 * det * det))) / 2));
}

}  // namespace shadowlab
