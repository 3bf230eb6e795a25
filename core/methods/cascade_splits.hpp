#pragma once
// Where the cascades split the view's depth range [near, far] (Zhang et al. 2006, parallel-split
// shadow maps): count + 1 depths C_0 = near < C_1 < ... < C_m = far,
// cascade i serving view depths [C_i, C_i+1].
#include <vector>

namespace shadowlab {

// PSSM's practical scheme: C_i = λ n (f/n)^(i/m) + (1 - λ) (n + (f - n) i/m), the logarithmic split
// (λ = 1: every split the same ratio far/near, as perspective aliasing asks) blended with the
// uniform one (λ = 0), which the logarithmic split starves far away.
std::vector<double> practical_splits(double near, double far, int count, double lambda);

// Manual splits: C_i = n + fractions[i - 1] (f - n) for the given fractions of the depth range
// (count - 1 of them, increasing, within (0, 1)).
std::vector<double> manual_splits(double near, double far, const std::vector<double>& fractions);

}  // namespace shadowlab
