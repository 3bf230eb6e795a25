#include "scene/polygon_triangulation.hpp"

#include <cmath>

namespace shadowlab {
namespace {

// Newell's normal: the polygon's area vector, sound for a concave or slightly non-planar face.
glm::dvec3 newell_normal(const std::vector<glm::dvec3>& vertices, std::span<const int> corners) {
    glm::dvec3 normal(0.0);
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const glm::dvec3& a = vertices[corners[i]];
        const glm::dvec3& b = vertices[corners[(i + 1) % corners.size()]];
        normal += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    return normal;
}

// The corners in the plane of the normal's largest component, turned so that the polygon winds
// counter-clockwise there.
std::vector<glm::dvec2> flattened(const std::vector<glm::dvec3>& vertices, std::span<const int> corners,
                                  const glm::dvec3& normal) {
    const glm::dvec3 size = glm::abs(normal);
    const int drop = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
    const int u = (drop + 1) % 3, v = (drop + 2) % 3;
    const double turn = normal[drop] >= 0.0 ? 1.0 : -1.0;
    std::vector<glm::dvec2> flat;
    for (int corner : corners) flat.push_back({vertices[corner][u], turn * vertices[corner][v]});
    return flat;
}

double cross(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool inside_triangle(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return cross(a, b, p) >= 0.0 && cross(b, c, p) >= 0.0 && cross(c, a, p) >= 0.0;
}

// Corner `at` of the remaining ring is an ear: convex, and no other remaining corner in its triangle.
bool is_ear(const std::vector<glm::dvec2>& flat, const std::vector<std::size_t>& ring, std::size_t at) {
    const std::size_t n = ring.size();
    const glm::dvec2 &a = flat[ring[(at + n - 1) % n]], &b = flat[ring[at]], &c = flat[ring[(at + 1) % n]];
    if (!(cross(a, b, c) > 0.0)) return false;
    for (std::size_t k = 0; k < n; ++k) {
        if (k == at || k == (at + 1) % n || k == (at + n - 1) % n) continue;
        const glm::dvec2& p = flat[ring[k]];
        if (p != a && p != b && p != c && inside_triangle(p, a, b, c)) return false;
    }
    return true;
}

bool convex(const std::vector<glm::dvec2>& flat) {
    const std::size_t n = flat.size();
    for (std::size_t i = 0; i < n; ++i)
        if (!(cross(flat[i], flat[(i + 1) % n], flat[(i + 2) % n]) > 0.0)) return false;
    return true;
}

void fan(std::span<const int> corners, std::vector<std::array<int, 3>>& out) {
    for (std::size_t i = 1; i + 1 < corners.size(); ++i) out.push_back({corners[0], corners[i], corners[i + 1]});
}

}  // namespace

std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<glm::dvec3>& vertices,
                                                    std::span<const int> corners) {
    std::vector<std::array<int, 3>> triangles;
    if (corners.size() < 3) return triangles;
    if (corners.size() == 3 || corners.size() > kMaxEarClippedCorners) {
        fan(corners, triangles);
        return triangles;
    }
    const std::vector<glm::dvec2> flat = flattened(vertices, corners, newell_normal(vertices, corners));
    if (convex(flat)) {  // a fan from the first corner, as Assimp cuts a convex face
        fan(corners, triangles);
        return triangles;
    }
    std::vector<std::size_t> ring(corners.size());
    for (std::size_t i = 0; i < ring.size(); ++i) ring[i] = i;
    while (ring.size() > 3) {
        std::size_t ear = 0;
        while (ear < ring.size() && !is_ear(flat, ring, ear)) ++ear;
        if (ear == ring.size()) break;  // no ear: a twisted or degenerate face, fanned below
        const std::size_t n = ring.size();
        triangles.push_back({corners[ring[(ear + n - 1) % n]], corners[ring[ear]], corners[ring[(ear + 1) % n]]});
        ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(ear));
    }
    std::vector<int> rest;
    for (std::size_t index : ring) rest.push_back(corners[index]);
    fan(rest, triangles);
    return triangles;
}

}  // namespace shadowlab
