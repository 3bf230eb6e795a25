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

SeenReceivers receivers_seen(const Scene& scene, const ReferenceImage& seen) {
    SeenReceivers out{.image_height = seen.height};
    for (size_t i = 0; i < seen.visible.size(); ++i)
        if (seen.visible[i] && scene.objects[seen.object[i]].receives) out.points.push_back(seen.position[i]);
    return out;
}

void read_depth_image(ShadowInputs& inputs, const Scene& scene, const ReferenceImage& seen) {
    inputs.visible_depths = receiver_depth_range(scene, seen);
    inputs.seen_receivers = receivers_seen(scene, seen);
}

void trace_depth_image(ShadowInputs& inputs, const Scene& scene, const WorldTriangles& triangles, int width,
                       int height) {
    read_depth_image(inputs, scene, visible_points(scene, triangles, width, height));
}

DepthRange trace_receiver_depth_range(const Scene& scene, const WorldTriangles& triangles, int width, int height) {
    return receiver_depth_range(scene, visible_points(scene, triangles, width, height));
}

}  // namespace shadowlab
