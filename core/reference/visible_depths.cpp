#include "reference/visible_depths.hpp"

#include <algorithm>
#include <limits>

namespace shadowlab {

DepthRange receiver_depth_range(const Scene& scene, const ReferenceImage& seen) {
    const Camera& camera = scene.camera;
    const glm::dvec3 view_axis = camera.view_direction();
    double nearest = std::numeric_limits<double>::infinity(), farthest = -nearest;
    for (size_t i = 0; i < seen.visible.size(); ++i) {
        if (!seen.visible[i] || !scene.objects[seen.object[i]].receives) continue;
        const double depth = glm::dot(seen.position[i] - camera.position, view_axis);
        nearest = std::min(nearest, depth);
        farthest = std::max(farthest, depth);
    }
    if (nearest > farthest) return {};  // none seen
    return DepthRange{.near = std::max(camera.near, nearest * (1.0 - kVisibleDepthMargin)),
                      .far = std::min(camera.far, farthest * (1.0 + kVisibleDepthMargin))};
}

DepthRange trace_receiver_depth_range(const Scene& scene, const WorldTriangles& triangles, int width, int height) {
    return receiver_depth_range(scene, visible_points(scene, triangles, width, height));
}

}  // namespace shadowlab
