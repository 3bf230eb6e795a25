#pragma once
// The one light of a scene.
#include <optional>
#include <glm/glm.hpp>

namespace shadowlab {

enum class LightType { directional, spot, point };

// The distances from a spot or point light its map's depth spans: nothing nearer casts, nothing
// farther is lit (a lamp's reach). 0 < near < far.
struct LightRange {
    double near = 0.0, far = 0.0;
};

const char* to_string(LightType type);

struct Light {
    LightType type = LightType::directional;
    glm::dvec3 direction{-0.3, -1.0, -0.2};  // unit; the way the light travels (directional, spot)
    glm::dvec3 position{0.0, 10.0, 0.0};     // spot and point lights
    double cone_deg = 60.0;                  // spot: full apex angle of the cone
    std::optional<LightRange> range;         // spot and point; none: the maps fit the scene's distances
    // Area lights (soft shadows; 0: hard): a spot or point light as a sphere of this radius, the sun
    // as a disc of this angular radius.
    double radius = 0.0;
    double angular_radius_deg = 0.0;

    bool is_directional() const { return type == LightType::directional; }
    bool is_area() const { return is_directional() ? angular_radius_deg > 0.0 : radius > 0.0; }
    // The light as a homogeneous point: (position, 1), or (-direction, 0) at infinity.
    glm::dvec4 homogeneous() const {
        return is_directional() ? glm::dvec4(-direction, 0.0) : glm::dvec4(position, 1.0);
    }
};

// A directional light's direction by the sky position it shines from: azimuth in degrees about +y,
// 0 at +x and 90 at +z; elevation in degrees above the ground plane (y = 0). Gives the unit vector
// the light travels along, from that position down toward the origin.
glm::dvec3 light_direction_from_angles(double azimuth_deg, double elevation_deg);

// The inverse: the azimuth in [0, 360) and elevation in [-90, 90] of the sky position a light
// travelling along `direction` (any length) shines from.
struct LightAngles {
    double azimuth_deg, elevation_deg;
};
LightAngles light_angles(const glm::dvec3& direction);

}  // namespace shadowlab
