#pragma once
// Flatland (Lloyd, Govindaraju, Quammen, Molnar and Manocha 2008 analyse shadow maps in it): the
// plane through the eye spanned by the view direction V and the light direction L. It holds the
// view axis, so a map's sampling along the view is seen there whole, and the light's rays through
// the view axis, so a texel's column toward the light stays in it.
#include <optional>
#include <glm/glm.hpp>

#include "geometry/plane.hpp"
#include "notes/note.hpp"
#include "scene/camera.hpp"
#include "scene/light.hpp"

namespace shadowlab {

// The plane with its own 2-D frame: (s, t) = the eye at the origin, s along V (the picture's
// horizontal axis, the eye at its left), t across V against the light (up in the picture: the
// light comes from above). along, across and normal() are orthonormal and right-handed.
struct FlatlandPlane {
    glm::dvec3 eye{0.0};
    glm::dvec3 along{0, 0, -1};  // V
    glm::dvec3 across{0, 1, 0};  // ⟂ V in the plane; the light's direction has a component along −across

    glm::dvec3 normal() const { return glm::cross(along, across); }
    Plane plane() const { return Plane::through(eye, normal()); }
    glm::dvec2 coordinates(const glm::dvec3& world) const {
        return {glm::dot(world - eye, along), glm::dot(world - eye, across)};
    }
    glm::dvec3 world(const glm::dvec2& st) const { return eye + st.x * along + st.y * across; }
    // World -> (s, t, signed distance off the plane): a rigid motion.
    glm::dmat4 plane_from_world() const;
};

// The light's direction at the eye: a directional light's own, a spot or point light's from its
// position to the eye.
glm::dvec3 light_direction_at(const Light& light, const glm::dvec3& p);

struct FlatlandChoice {
    FlatlandPlane plane;
    std::optional<Note> fallback;  // light_along_view: no plane holds V and L apart; V and the camera's up span it
};

// Below this sine of the angle between V and L the two no longer span a plane one can trust.
constexpr double kLeastSinViewLight = 1e-3;

// The flatland plane of a camera and a light.
FlatlandChoice flatland_plane(const Camera& camera, const Light& light);

}  // namespace shadowlab
