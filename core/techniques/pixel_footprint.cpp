#include "techniques/pixel_footprint.hpp"

#include <algorithm>
#include <cmath>

namespace shadowlab {

PixelBox pixel_footprint(const glm::dmat4& world_to_clip, const CameraRays& rays, const HomogeneousPolygon& polygon) {
    // Near (z >= -w) and the four sides (-w <= x, y <= w); no far plane.
    static const ClipPlane planes[] = {
        {{0, 0, 1, 1}, 0.0}, {{1, 0, 0, 1}, 0.0}, {{-1, 0, 0, 1}, 0.0}, {{0, 1, 0, 1}, 0.0}, {{0, -1, 0, 1}, 0.0}};
    HomogeneousPolygon clipped;
    for (const glm::dvec4& v : polygon) clipped.push_back(world_to_clip * v);
    for (const ClipPlane& plane : planes) clipped = clip(clipped, plane);
    if (clipped.empty()) return {};
    const PixelBox whole{0, 0, rays.width() - 1, rays.height() - 1};
    glm::dvec2 lo(INFINITY), hi(-INFINITY);
    for (const glm::dvec4& h : clipped) {
        // After the side planes |x|, |y| <= w; w = 0 is left only where the clipped polygon
        // touches the eye itself: then every pixel may be covered.
        if (!(h.w > 0.0)) return whole;
        const glm::dvec2 p = rays.pixel_of_ndc(glm::clamp(glm::dvec2(h) / h.w, -1.0, 1.0));
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return {std::max(whole.x0, int(std::floor(lo.x)) - 1), std::max(whole.y0, int(std::floor(lo.y)) - 1),
            std::min(whole.x1, int(std::ceil(hi.x)) + 1), std::min(whole.y1, int(std::ceil(hi.y)) + 1)};
}

}  // namespace shadowlab
