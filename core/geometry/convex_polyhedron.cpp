#include "geometry/convex_polyhedron.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace shadowlab {

Aabb ConvexPolyhedron::bounds() const {
    Aabb box;
    for (const glm::dvec3& v : vertices) box.extend(v);
    return box;
}

glm::dvec3 ConvexPolyhedron::centroid() const {
    glm::dvec3 sum{0.0};
    for (const glm::dvec3& v : vertices) sum += v;
    return vertices.empty() ? sum : sum / double(vertices.size());
}

// Sum of signed tetrahedra from an inner point to each face fan (divergence theorem).
double ConvexPolyhedron::volume() const {
    if (empty()) return 0.0;
    const glm::dvec3 o = centroid();
    double six_volume = 0.0;
    for (const PolyFace& f : faces)
        for (size_t i = 1; i + 1 < f.loop.size(); ++i)
            six_volume +=
                glm::dot(vertices[f.loop[0]] - o, glm::cross(vertices[f.loop[i]] - o, vertices[f.loop[i + 1]] - o));
    return six_volume / 6.0;
}

ConvexPolyhedron ConvexPolyhedron::box(const Aabb& b) {
    ConvexPolyhedron p;
    if (b.empty()) return p;
    const auto c = b.corners();  // bit 0: x, bit 1: y, bit 2: z
    p.vertices.assign(c.begin(), c.end());
    auto face = [&](std::vector<int> loop, glm::dvec3 n, const glm::dvec3& on) {
        p.faces.push_back({std::move(loop), Plane::through(on, n)});
    };
    face({0, 4, 6, 2}, {-1, 0, 0}, b.min);
    face({1, 3, 7, 5}, {1, 0, 0}, b.max);
    face({0, 1, 5, 4}, {0, -1, 0}, b.min);
    face({2, 6, 7, 3}, {0, 1, 0}, b.max);
    face({0, 2, 3, 1}, {0, 0, -1}, b.min);
    face({4, 5, 7, 6}, {0, 0, 1}, b.max);
    return p;
}

namespace {

enum class Side { inside, on, outside };

// Orders the cap's vertices counter-clockwise around `normal` (seen from outside).
std::vector<int> sorted_cap(const std::vector<glm::dvec3>& vertices, std::vector<int> cap, const glm::dvec3& normal) {
    glm::dvec3 centre{0.0};
    for (int i : cap) centre += vertices[i];
    centre /= double(cap.size());
    const glm::dvec3 helper = std::abs(normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 a = glm::normalize(glm::cross(normal, helper));
    const glm::dvec3 b = glm::cross(normal, a);
    std::vector<std::pair<double, int>> by_angle;
    by_angle.reserve(cap.size());
    for (int i : cap) {
        const glm::dvec3 d = vertices[i] - centre;
        by_angle.emplace_back(std::atan2(glm::dot(d, b), glm::dot(d, a)), i);
    }
    std::sort(by_angle.begin(), by_angle.end());
    for (size_t k = 0; k < cap.size(); ++k) cap[k] = by_angle[k].second;
    return cap;
}

// Drops vertices no face uses and renumbers the loops.
ConvexPolyhedron compacted(const std::vector<glm::dvec3>& vertices, std::vector<PolyFace> faces) {
    ConvexPolyhedron out;
    std::vector<int> remap(vertices.size(), -1);
    for (PolyFace& f : faces)
        for (int& i : f.loop) {
            if (remap[i] < 0) {
                remap[i] = int(out.vertices.size());
                out.vertices.push_back(vertices[i]);
            }
            i = remap[i];
        }
    out.faces = std::move(faces);
    return out;
}

}  // namespace

ConvexPolyhedron clip(const ConvexPolyhedron& poly, const Plane& plane, double tolerance) {
    std::vector<double> distance(poly.vertices.size());
    std::vector<Side> side(poly.vertices.size());
    bool any_inside = false, any_outside = false;
    for (size_t i = 0; i < poly.vertices.size(); ++i) {
        distance[i] = plane.signed_distance(poly.vertices[i]);
        side[i] = distance[i] < -tolerance ? Side::inside : distance[i] > tolerance ? Side::outside : Side::on;
        any_inside |= side[i] == Side::inside;
        any_outside |= side[i] == Side::outside;
    }
    if (!any_outside) return poly;
    if (!any_inside) return {};

    std::vector<glm::dvec3> vertices = poly.vertices;
    std::vector<std::pair<std::pair<int, int>, int>> cut_vertex;  // one new vertex per crossing edge
    auto crossing = [&](int a, int b) {
        const std::pair<int, int> key = std::minmax(a, b);
        for (const auto& [edge, index] : cut_vertex)
            if (edge == key) return index;
        const double t = distance[a] / (distance[a] - distance[b]);
        vertices.push_back(glm::mix(poly.vertices[a], poly.vertices[b], t));
        cut_vertex.push_back({key, int(vertices.size()) - 1});
        return int(vertices.size()) - 1;
    };

    std::vector<PolyFace> faces;
    std::vector<int> cap;
    for (const PolyFace& f : poly.faces) {
        PolyFace kept{{}, f.plane};
        for (size_t k = 0; k < f.loop.size(); ++k) {
            const int a = f.loop[k], b = f.loop[(k + 1) % f.loop.size()];
            if (side[a] != Side::outside) kept.loop.push_back(a);
            if (side[a] == Side::on) cap.push_back(a);
            if ((side[a] == Side::inside && side[b] == Side::outside) ||
                (side[a] == Side::outside && side[b] == Side::inside)) {
                kept.loop.push_back(crossing(a, b));
                cap.push_back(kept.loop.back());
            }
        }
        if (kept.loop.size() >= 3) faces.push_back(std::move(kept));
    }
    std::sort(cap.begin(), cap.end());
    cap.erase(std::unique(cap.begin(), cap.end()), cap.end());
    if (cap.size() >= 3) faces.push_back({sorted_cap(vertices, cap, plane.normal), plane});
    ConvexPolyhedron out = compacted(vertices, std::move(faces));
    return out.empty() ? ConvexPolyhedron{} : out;
}

bool is_closed(const ConvexPolyhedron& poly) {
    if (poly.empty()) return false;
    std::map<std::pair<int, int>, int> directed;
    for (const PolyFace& f : poly.faces) {
        if (f.loop.size() < 3) return false;
        for (size_t k = 0; k < f.loop.size(); ++k) ++directed[{f.loop[k], f.loop[(k + 1) % f.loop.size()]}];
    }
    for (const auto& [edge, count] : directed) {
        auto twin = directed.find({edge.second, edge.first});
        if (count != 1 || twin == directed.end() || twin->second != 1) return false;
    }
    return true;
}

bool is_convex(const ConvexPolyhedron& poly, double tolerance) {
    for (const PolyFace& f : poly.faces)
        for (const glm::dvec3& v : poly.vertices)
            if (f.plane.signed_distance(v) > tolerance) return false;
    return !poly.empty();
}

}  // namespace shadowlab
