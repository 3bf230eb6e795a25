#pragma once
// An oriented plane n.x + offset = 0; the inside (kept) half-space is n.x + offset <= 0.
#include <glm/glm.hpp>

namespace shadowlab {

struct Plane {
    glm::dvec3 normal{0.0, 0.0, 1.0};  // unit, pointing out of the kept half-space
    double offset = 0.0;

    double signed_distance(const glm::dvec3& p) const { return glm::dot(normal, p) + offset; }
    // Homogeneous point (x, w): w = 0 is a direction (a point at infinity).
    double signed_distance(const glm::dvec4& p) const { return glm::dot(normal, glm::dvec3(p)) + offset * p.w; }

    // Plane through a point with an outward normal (normalised here).
    static Plane through(const glm::dvec3& point, const glm::dvec3& outward_normal) {
        glm::dvec3 n = glm::normalize(outward_normal);
        return {n, -glm::dot(n, point)};
    }
};

}  // namespace shadowlab
