#include "methods/cascade_splits.hpp"

#include <cmath>

namespace shadowlab {

std::vector<double> practical_splits(double near, double far, int count, double lambda) {
    std::vector<double> depths{near};
    for (int i = 1; i < count; ++i) {
        const double share = double(i) / count;
        const double logarithmic = near * std::pow(far / near, share);
        const double uniform = near + (far - near) * share;
        depths.push_back(lambda * logarithmic + (1.0 - lambda) * uniform);
    }
    depths.push_back(far);  // exactly the far end, not the formula's rounding of it
    return depths;
}

std::vector<double> manual_splits(double near, double far, const std::vector<double>& fractions) {
    std::vector<double> depths{near};
    for (double fraction : fractions) depths.push_back(near + fraction * (far - near));
    depths.push_back(far);
    return depths;
}

}  // namespace shadowlab
