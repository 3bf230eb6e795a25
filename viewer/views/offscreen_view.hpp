#pragma once
// A view drawn to pixels without showing a window (under an X server: Xvfb in tests and CI).
#include "render/rgb_image.hpp"
#include "views/view.hpp"

namespace shadowlab {

// Throws std::runtime_error without an X display, std::invalid_argument for an unknown step.
RgbImage render_view(const Inspection& inspection, const View& view, const ViewOptions& options, int width, int height);

}  // namespace shadowlab
