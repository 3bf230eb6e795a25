#pragma once
// The conventions an engine writes its matrices in, as settings: one spec and one reader per
// convention, shared by the custom method (a light's matrices) and the camera import, so that both
// name them alike (README: Debugging your engine).
#include "io/matrix_text.hpp"
#include "maps/clip_conventions.hpp"
#include "methods/settings.hpp"

namespace shadowlab {

SettingSpec storage_setting();     // storage: auto | column_major | row_major
SettingSpec clip_depth_setting();  // clip_depth: minus_one_to_one (OpenGL) | zero_to_one (Direct3D, Vulkan)
SettingSpec reversed_z_setting();  // reversed_z: off | on

MatrixStorage storage_of(const Settings& settings);
ClipDepth clip_depth_of(const Settings& settings);
bool reversed_z_of(const Settings& settings);

}  // namespace shadowlab
