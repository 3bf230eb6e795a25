#pragma once
// Which OpenGL implementation VTK draws with. A software one (Mesa's llvmpipe under Xvfb) draws
// every fragment on the CPU the window also computes with: the window turns multisampling off there
// (8 samples a pixel cost a software rasterizer about twice the time of the whole frame without).
#include <string>

namespace shadowlab {

// The renderer string of the OpenGL VTK gets on this display ("llvmpipe (LLVM 15.0.6, 256 bits)"),
// probed once with a 1 x 1 offscreen window; empty if none could be made.
const std::string& opengl_renderer();
// Does the renderer string name a software rasterizer (llvmpipe, softpipe, swrast)?
bool is_software_renderer(const std::string& renderer);

}  // namespace shadowlab
