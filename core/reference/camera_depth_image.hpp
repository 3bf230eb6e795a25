#pragma once
// The camera's depth image contact shadows march in (lookup/contact_shadow.hpp), read from the
// visible points a reference (or visible_points) traced: the same pixels the lookups judge.
#include "lookup/contact_shadow.hpp"
#include "reference/exact_shadows.hpp"

namespace shadowlab {

// Each visible pixel's window depth, 1 where the image sees nothing.
CameraDepthImage camera_depth_image(const Camera& camera, const ReferenceImage& seen);

}  // namespace shadowlab
