#pragma once
// Sutherland-Hodgman clipping of a convex polygon with homogeneous vertices against half-spaces
// normal . h >= offset: clipping before the division by w keeps points at or behind w = 0 right.
#include <cstddef>
#include <vector>
#include <glm/glm.hpp>

namespace shadowlab {

using HomogeneousPolygon = std::vector<glm::dvec4>;  // convex, in order

struct ClipPlane {
    glm::dvec4 normal;
    double offset;
};

// The part of the polygon in one half-space; new points interpolate the homogeneous coordinates.
inline HomogeneousPolygon clip(const HomogeneousPolygon& polygon, const ClipPlane& plane) {
    HomogeneousPolygon out;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec4& a = polygon[i];
        const glm::dvec4& b = polygon[(i + 1) % polygon.size()];
        const double da = glm::dot(plane.normal, a) - plane.offset;
        const double db = glm::dot(plane.normal, b) - plane.offset;
        if (da >= 0.0) out.push_back(a);
        if ((da >= 0.0) != (db >= 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

}  // namespace shadowlab
