#pragma once
// One aspect rule for every image of the camera (measure, bench, sweep, render, the window): the
// image keeps the scene camera's aspect, so its pixels are square and its camera is the scene's,
// the same matrices everywhere. Asked for a size of another shape, the image shrinks to fit in it.
#include <glm/glm.hpp>

#include "scene/camera.hpp"

namespace shadowlab {

// The largest width x height of the camera's aspect within the asked size (each side at least 1).
glm::ivec2 image_size_within(const Camera& camera, int width, int height);

}  // namespace shadowlab
