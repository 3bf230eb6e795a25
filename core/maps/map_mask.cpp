#include "maps/map_mask.hpp"

#include <algorithm>

namespace shadowlab {

glm::dvec3 left_of(const glm::dvec2& from, const glm::dvec2& to) {
    const glm::dvec2 along = to - from;
    const glm::dvec2 inward{-along.y, along.x};                // along turned a quarter counter-clockwise
    return glm::dvec3(inward, -glm::dot(inward, from)) + 0.0;  // + 0: no -0 in the exports
}

bool in_mask(const ShadowMap& map, const glm::dvec2& uv) {
    return std::all_of(map.mask.begin(), map.mask.end(),
                       [&](const glm::dvec3& half) { return glm::dot(half, glm::dvec3(uv, 1.0)) >= 0.0; });
}

std::vector<ClipPlane> mask_clip_planes(const ShadowMap& map) {
    std::vector<ClipPlane> planes;
    for (const glm::dvec3& half : map.mask) planes.push_back({.normal = {half.x, half.y, 0.0, half.z}, .offset = 0.0});
    return planes;
}

std::vector<glm::dvec2> mask_outline(const ShadowMap& map) {
    HomogeneousPolygon square{{0, 0, 0, 1}, {1, 0, 0, 1}, {1, 1, 0, 1}, {0, 1, 0, 1}};
    for (const ClipPlane& plane : mask_clip_planes(map)) square = clip(square, plane);
    std::vector<glm::dvec2> outline;  // a corner on a cutting line comes back twice: once
    for (const glm::dvec4& h : square) {
        const glm::dvec2 corner(h.x / h.w, h.y / h.w);
        if (outline.empty() || corner != outline.back()) outline.push_back(corner);
    }
    if (outline.size() > 1 && outline.front() == outline.back()) outline.pop_back();
    return outline;
}

double mask_area(const ShadowMap& map) {
    const std::vector<glm::dvec2> outline = mask_outline(map);
    double twice = 0.0;  // the shoelace formula
    for (size_t k = 0; k < outline.size(); ++k) {
        const glm::dvec2 a = outline[k], b = outline[(k + 1) % outline.size()];
        twice += a.x * b.y - a.y * b.x;
    }
    return twice / 2.0;
}

}  // namespace shadowlab
