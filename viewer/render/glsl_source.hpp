#pragma once
// The shaders' GLSL, one file per concept in render/glsl/ (each named like its C++ twin: depth_bias.glsl
// is lookup/depth_bias.cpp's), embedded in the build: viewer/CMakeLists.txt runs
// render/glsl/embed_glsl.cmake, which regenerates the table whenever a .glsl file changes.
#include <string_view>

namespace shadowlab {

// The text of render/glsl/<name>.glsl; nullptr when there is no such file.
const std::string_view* find_glsl(std::string_view name);
// The same, or std::invalid_argument naming the missing file.
std::string_view glsl_source(std::string_view name);

}  // namespace shadowlab
