#include "lookup/pcss.hpp"

#include <cmath>

namespace shadowlab {

double penumbra_width(double receiver_distance, double blocker_distance, double light_width) {
    return (receiver_distance - blocker_distance) * light_width / blocker_distance;
}

double penumbra_width(const Light& light, const glm::dvec3& p, double delta) {
    if (light.is_directional()) return 2.0 * delta * std::tan(glm::radians(light.angular_radius_deg));
    const double receiver_distance = glm::distance(p, light.position);
    const double blocker_distance = receiver_distance - delta;
    if (!(blocker_distance > 0.0)) return INFINITY;
    return penumbra_width(receiver_distance, blocker_distance, 2.0 * light.radius);
}

double blocker_search_radius(const Light& light, const glm::dvec3& p, double delta) {
    return penumbra_width(light, p, delta) / 2.0;
}

}  // namespace shadowlab
