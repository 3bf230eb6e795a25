#include "lookup/moment_shadow.hpp"

#include <algorithm>
#include <cmath>

namespace shadowlab {
namespace {

// Supplementary listing 1 of Peters and Klein (2015), row by row as the paper writes the row-vector
// product b · M; a GLM matrix built from the same sixteen numbers holds them column by column, so
// that M * b is that same product.
const glm::dmat4 kOptimizedFromPower(-2.07224649, 13.7948857237, 0.105877704, 9.7924062118,       //
                                     32.23703778, -59.4683975703, -1.9077466311, -33.7652110555,  //
                                     -68.571074599, 82.0359750338, 9.3496555107, 47.9456096605,   //
                                     39.3703274134, -35.364903257, -6.6543490743, -23.9728048165);
const glm::dmat4 kPowerFromOptimized(0.2227744146, 0.1549679261, 0.1451988946, 0.163127443,   //
                                     0.0771972861, 0.1394629426, 0.2120202157, 0.2591432266,  //
                                     0.7926986636, 0.7963415838, 0.7258694464, 0.6539092497,  //
                                     0.0319417555, -0.1722823173, -0.2758014811, -0.3376131734);
const glm::dvec4 kOptimizedOffset(0.035955884801, 0.0, 0.0, 0.0);
const glm::dvec4 kBiasTarget(0.5, 11.0 / 32, 17.0 / 64, 29.0 / 128);  // hamburger_shadow_intensity's b*

}  // namespace

glm::dvec4 power_moments(double depth) {
    const double square = depth * depth;
    return {depth, square, square * depth, square * square};
}

glm::dvec4 optimized_moments(const glm::dvec4& power) { return kOptimizedFromPower * power + kOptimizedOffset; }

glm::dvec4 power_from_optimized(const glm::dvec4& optimized) {
    return kPowerFromOptimized * (optimized - kOptimizedOffset);
}

glm::dvec4 rounded_to_unorm16(const glm::dvec4& value) {
    constexpr double kSteps = 65535.0;
    return glm::round(glm::clamp(value, 0.0, 1.0) * kSteps) / kSteps;
}

double hamburger_shadow_intensity(const glm::dvec4& moments, double depth, double moment_bias) {
    // Step 1: b' = (1 − α) b + α b*, b* the moments of depths 0, ½ and 1 in the shares 3/16, 5/8
    // and 3/16: Peters' (0, 0.375, 0, 0.375) on [−1, 1] carried to [0, 1]. Three depths keep B
    // positive definite whatever b is; (½, ½, ½, ½), depths 0 and 1 alone, which MJP's sample pulls
    // toward, leaves B singular for casters at depth 0, where a fitted map puts its nearest ones.
    const glm::dvec4 b = glm::mix(moments, kBiasTarget, moment_bias);
    const double b1 = b.x, b2 = b.y, b3 = b.z, b4 = b.w, z = depth;
    // Step 2: solve B c = (1, z, z²)ᵀ, B = [[1, b1, b2], [b1, b2, b3], [b2, b3, b4]] the Hankel
    // matrix, by its Cholesky factorization L D Lᵀ (L21 = b1, L31 = b2).
    const double d22 = b2 - b1 * b1;
    const double l32 = (b3 - b1 * b2) / d22;
    const double d33 = b4 - b2 * b2 - l32 * l32 * d22;
    const double y2 = z - b1;  // forward substitution: L y = (1, z, z²)
    const double y3 = z * z - b2 - l32 * y2;
    const double c3 = y3 / d33;  // the scaling by D, then back substitution: Lᵀ c = D⁻¹ y
    const double c2 = y2 / d22 - l32 * c3;
    const double c1 = 1.0 - b1 * c2 - b2 * c3;
    // Step 3: the other two support points z2 <= z3 of the bound's distribution, the roots of
    // c1 + c2 x + c3 x².
    const double p = c2 / c3, q = c1 / c3;
    const double r = std::sqrt(std::max(p * p / 4.0 - q, 0.0));
    const double z2 = -p / 2.0 - r, z3 = -p / 2.0 + r;
    // Step 4: the weight of the support points nearer the light than z.
    double g = 0.0;
    if (z > z3)
        g = 1.0 - (z2 * z3 - b1 * (z2 + z3) + b2) / ((z - z2) * (z - z3));
    else if (z > z2)
        g = (z * z3 - b1 * (z + z3) + b2) / ((z3 - z2) * (z - z2));
    return std::clamp(g, 0.0, 1.0);
}

}  // namespace shadowlab
