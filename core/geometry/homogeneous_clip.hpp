#pragma once
// Sutherland-Hodgman clipping of a convex polygon with homogeneous vertices against half-spaces
// normal . h >= offset: clipping before the division by w keeps points at or behind w = 0 right.
#include <cstddef>
#include <vector>
#include <glm/glm.hpp>

namespace shadowlab {

using HomogeneousPolygon = std::vector<glm::dvec4>;  // convex, in order

// The polygon moved by `offset`: points move, points at infinity (w = 0) stay.
inline HomogeneousPolygon translated(HomogeneousPolygon polygon, const glm::dvec3& offset) {
    for (glm::dvec4& v : polygon) v += glm::dvec4(offset * v.w, 0.0);
    return polygon;
}

struct ClipPlane {
    glm::dvec4 normal;
    double offset;
};

// The part of the polygon where distance(i), a value given at each vertex i and interpolated along
// the edges (as a GPU interpolates gl_ClipDistance), is >= 0; new points interpolate the
// homogeneous coordinates.
template <class Distance>
HomogeneousPolygon clip_where(const HomogeneousPolygon& polygon, Distance&& distance) {
    HomogeneousPolygon out;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const std::size_t j = (i + 1) % polygon.size();
        const glm::dvec4 &a = polygon[i], &b = polygon[j];
        const double da = distance(i), db = distance(j);
        if (da >= 0.0) out.push_back(a);
        if ((da >= 0.0) != (db >= 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

// The part of the polygon in one half-space.
inline HomogeneousPolygon clip(const HomogeneousPolygon& polygon, const ClipPlane& plane) {
    return clip_where(polygon, [&](std::size_t i) { return glm::dot(plane.normal, polygon[i]) - plane.offset; });
}

}  // namespace shadowlab
