#include "geometry/plane_section.hpp"

#include <algorithm>
#include <cmath>

namespace shadowlab {
namespace {

// Two vectors spanning the plane, so that corners can be ordered by their angle about the centroid.
std::pair<glm::dvec3, glm::dvec3> plane_axes(const glm::dvec3& normal) {
    const glm::dvec3 helper = std::abs(normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 a = glm::normalize(glm::cross(helper, normal));
    return {a, glm::cross(normal, a)};
}

void add_distinct(std::vector<glm::dvec3>& corners, const glm::dvec3& p, double tolerance) {
    for (const glm::dvec3& q : corners)
        if (glm::length(p - q) <= tolerance) return;
    corners.push_back(p);
}

}  // namespace

std::vector<Edge> edges_of(const ConvexPolyhedron& solid) {
    std::vector<Edge> edges;
    for (const PolyFace& face : solid.faces)
        for (size_t i = 0; i < face.loop.size(); ++i)
            edges.emplace_back(solid.vertices[face.loop[i]], solid.vertices[face.loop[(i + 1) % face.loop.size()]]);
    return edges;
}

std::vector<Edge> edges_of(const Frustum& f) {
    std::vector<Edge> edges;
    for (int i = 0; i < 4; ++i) {
        edges.emplace_back(f.corners[i], f.corners[(i + 1) % 4]);          // the near face's loop
        edges.emplace_back(f.corners[4 + i], f.corners[4 + (i + 1) % 4]);  // the far face's
        edges.emplace_back(f.corners[i], f.corners[4 + i]);                // a side edge
    }
    return edges;
}

std::vector<glm::dvec3> plane_section(const std::vector<Edge>& edges, const Plane& plane) {
    double size = 0.0;
    for (const auto& [a, b] : edges) size = std::max({size, glm::length(a), glm::length(b)});
    const double tolerance = 1e-12 * std::max(size, 1.0);
    std::vector<glm::dvec3> corners;
    for (const auto& [a, b] : edges) {
        const double da = plane.signed_distance(a), db = plane.signed_distance(b);
        if (std::abs(da) <= tolerance) add_distinct(corners, a, tolerance);
        if (std::abs(db) <= tolerance) add_distinct(corners, b, tolerance);
        if ((da < -tolerance && db > tolerance) || (da > tolerance && db < -tolerance))
            add_distinct(corners, a + (b - a) * (da / (da - db)), tolerance);
    }
    if (corners.size() < 3) return {};
    glm::dvec3 centre(0.0);
    for (const glm::dvec3& c : corners) centre += c / static_cast<double>(corners.size());
    const auto axes = plane_axes(plane.normal);  // not a structured binding: clang 14 cannot capture one
    const auto angle = [&](const glm::dvec3& p) {
        return std::atan2(glm::dot(p - centre, axes.second), glm::dot(p - centre, axes.first));
    };
    std::sort(corners.begin(), corners.end(),
              [&](const glm::dvec3& p, const glm::dvec3& q) { return angle(p) < angle(q); });
    return corners;
}

}  // namespace shadowlab
