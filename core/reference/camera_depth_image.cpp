#include "reference/camera_depth_image.hpp"

namespace shadowlab {

CameraDepthImage camera_depth_image(const Camera& camera, const ReferenceImage& seen) {
    CameraDepthImage image(camera, seen.width, seen.height);
    for (size_t i = 0; i < seen.visible.size(); ++i)
        if (seen.visible[i]) image.window_depth[i] = float(image.window_depth_of(seen.position[i]));
    return image;
}

}  // namespace shadowlab
