#pragma once
// Axis-aligned bounding box in any space.
#include <array>
#include <limits>
#include <glm/glm.hpp>

namespace shadowlab {

struct Aabb {
    glm::dvec3 min{std::numeric_limits<double>::infinity()};
    glm::dvec3 max{-std::numeric_limits<double>::infinity()};

    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void extend(const glm::dvec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void extend(const Aabb& b) {
        if (!b.empty()) {
            extend(b.min);
            extend(b.max);
        }
    }
    glm::dvec3 center() const { return 0.5 * (min + max); }
    glm::dvec3 extent() const { return max - min; }
    double diagonal() const { return empty() ? 0.0 : glm::length(max - min); }
    bool contains(const glm::dvec3& p, double tolerance = 0.0) const {
        return glm::all(glm::greaterThanEqual(p, min - tolerance)) && glm::all(glm::lessThanEqual(p, max + tolerance));
    }
    bool overlaps(const Aabb& b) const {
        return !empty() && !b.empty() && glm::all(glm::lessThanEqual(min, b.max)) &&
               glm::all(glm::lessThanEqual(b.min, max));
    }
    // Corner i has bit 0 -> x, bit 1 -> y, bit 2 -> z taken from max.
    std::array<glm::dvec3, 8> corners() const {
        std::array<glm::dvec3, 8> c;
        for (int i = 0; i < 8; ++i) c[i] = {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z};
        return c;
    }
};

// Box of the transformed corners (affine transforms).
inline Aabb transformed(const Aabb& box, const glm::dmat4& m) {
    Aabb out;
    if (box.empty()) return out;
    for (const glm::dvec3& c : box.corners()) out.extend(glm::dvec3(m * glm::dvec4(c, 1.0)));
    return out;
}

}  // namespace shadowlab
