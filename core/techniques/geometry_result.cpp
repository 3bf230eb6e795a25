#include "techniques/geometry_result.hpp"

#include <algorithm>

namespace shadowlab {

GeometryCost geometry_cost(std::size_t polygons, const std::vector<int>& fragments) {
    GeometryCost cost{polygons, 0.0, 0.0};
    for (int f : fragments) {
        cost.fill_mean += double(f) / double(fragments.size());
        cost.fill_max = std::max(cost.fill_max, double(f));
    }
    return cost;
}

}  // namespace shadowlab
