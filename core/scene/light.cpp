#include "scene/light.hpp"

#include <algorithm>
#include <cmath>

namespace shadowlab {

const char* to_string(LightType type) {
    switch (type) {
        case LightType::directional: return "directional";
        case LightType::spot: return "spot";
        case LightType::point: return "point";
    }
    return "unknown";
}

glm::dvec3 light_direction_from_angles(double azimuth_deg, double elevation_deg) {
    const double azimuth = glm::radians(azimuth_deg), elevation = glm::radians(elevation_deg);
    const glm::dvec3 to_light(std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
                              std::cos(elevation) * std::sin(azimuth));
    return -to_light;
}

LightAngles light_angles(const glm::dvec3& direction) {
    const glm::dvec3 to_light = -glm::normalize(direction);
    const double azimuth = glm::degrees(std::atan2(to_light.z, to_light.x));
    return {.azimuth_deg = azimuth < 0.0 ? azimuth + 360.0 : azimuth,
            .elevation_deg = glm::degrees(std::asin(std::clamp(to_light.y, -1.0, 1.0)))};
}

}  // namespace shadowlab
