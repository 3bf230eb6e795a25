// The list of geometric techniques, and what they share.
#include <algorithm>

#include "planar/planar_technique.hpp"
#include "techniques/technique.hpp"
#include "volumes/volumes_technique.hpp"

namespace shadowlab {

GeometryCost geometry_cost(std::size_t polygons, const std::vector<int>& fragments) {
    GeometryCost cost{polygons, 0.0, 0.0};
    for (int f : fragments) {
        cost.fill_mean += double(f) / double(fragments.size());
        cost.fill_max = std::max(cost.fill_max, double(f));
    }
    return cost;
}

std::optional<std::string> joined_limits(const std::vector<std::string>& limits) {
    if (limits.empty()) return std::nullopt;
    std::string text;
    for (const std::string& limit : limits) text += (text.empty() ? "" : "; ") + limit;
    return text;
}

const std::vector<Technique>& all_techniques() {
    static const std::vector<Technique> techniques{
        {"volumes", "Stencil shadow volumes",
         "Crow, Heidmann, Everitt and Kilgard: silhouette edges extruded to infinity, faces counted per eye ray",
         {volumes_count_setting()}, compute_volumes},
        {"planar", "Planar projection shadows",
         "Blinn: the casters flattened onto each receiving plane by the matrix (P . L) I - L P^T", {}, compute_planar},
    };
    return techniques;
}

const Technique* find_technique(const std::string& name) {
    for (const Technique& t : all_techniques())
        if (t.name == name) return &t;
    return nullptr;
}

}  // namespace shadowlab
