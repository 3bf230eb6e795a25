#pragma once
// Oriented planes through homogeneous points (x, y, z, w), w = 0 being a point at infinity.
#include <cstddef>
#include <glm/glm.hpp>

#include "geometry/homogeneous_clip.hpp"

namespace shadowlab {

// The plane pi with pi . X = -det[A, B, C, X]: for finite points (w = 1) it is (n, -n . a),
// n = (b - a) x (c - a), so X is on its positive side when A, B, C turn counter-clockwise seen
// from X. Multilinear, hence right for points at infinity as limits of finite points.
inline glm::dvec4 plane_through(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c) {
    glm::dvec4 plane;
    for (int k = 0; k < 4; ++k) {
        glm::dvec4 e(0.0);
        e[k] = 1.0;
        plane[k] = -glm::determinant(glm::dmat4(a, b, c, e));
    }
    return plane;
}

// A convex polygon's plane as the sum of its fan triangles' planes: repeated vertices (an edge
// collapsed at infinity) add nothing instead of spoiling the result.
inline glm::dvec4 polygon_plane(const HomogeneousPolygon& polygon) {
    glm::dvec4 plane(0.0);
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i) plane += plane_through(polygon[0], polygon[i], polygon[i + 1]);
    return plane;
}

}  // namespace shadowlab
