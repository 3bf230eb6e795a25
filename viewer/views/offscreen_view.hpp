#pragma once
// A view drawn to pixels without showing a window (under an X server: Xvfb in tests and CI).
#include <functional>

#include "render/rgb_image.hpp"
#include "views/view.hpp"

namespace shadowlab {

// The view built into the renderer of an offscreen window of width x height, handed to `use` with
// its window and the view's report before the window is finalized. Throws std::runtime_error
// without an X display, std::invalid_argument for an unknown step.
using UseBuiltView = std::function<void(vtkRenderWindow*, vtkRenderer*, const ViewReport&)>;
void with_offscreen_view(const Inspection& inspection, const View& view, const ViewOptions& options, int width,
                         int height, const UseBuiltView& use);

// The view built and rendered; throws as with_offscreen_view.
RgbImage render_view(const Inspection& inspection, const View& view, const ViewOptions& options, int width, int height);

}  // namespace shadowlab
