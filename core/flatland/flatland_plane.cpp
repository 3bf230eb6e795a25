#include "flatland/flatland_plane.hpp"

#include <cmath>
#include <string>
#include <glm/gtc/matrix_transform.hpp>

#include "math/invariant.hpp"

namespace shadowlab {

glm::dmat4 FlatlandPlane::plane_from_world() const {
    const glm::dvec3 n = normal();
    glm::dmat4 rotation(1.0);  // rows along, across, normal
    for (int c = 0; c < 3; ++c) {
        rotation[c][0] = along[c];
        rotation[c][1] = across[c];
        rotation[c][2] = n[c];
    }
    return rotation * glm::translate(glm::dmat4(1.0), -eye);
}

glm::dvec3 light_direction_at(const Light& light, const glm::dvec3& p) {
    return light.is_directional() ? light.direction : glm::normalize(p - light.position);
}

FlatlandChoice flatland_plane(const Camera& camera, const Light& light) {
    FlatlandChoice choice;
    FlatlandPlane& plane = choice.plane;
    plane.eye = camera.position;
    plane.along = camera.view_direction();
    const glm::dvec3 l = light_direction_at(light, camera.position);
    // L's part across V; t points against it, so the light travels down the picture.
    glm::dvec3 across = -(l - glm::dot(l, plane.along) * plane.along);
    const double sin_view_light = glm::length(across);
    if (!(sin_view_light >= kLeastSinViewLight)) {
        choice.fallback =
            Note{NoteKind::light_along_view, "sin(V, L) = " + std::to_string(sin_view_light) +
                                                 ": the flatland plane is the one of V and the camera's up"};
        across = camera.up - glm::dot(camera.up, plane.along) * plane.along;
    }
    plane.across = glm::normalize(across);
    assert_invariant(std::abs(glm::dot(plane.along, plane.across)) < 1e-9);
    return choice;
}

}  // namespace shadowlab
