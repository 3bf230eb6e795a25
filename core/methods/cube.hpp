#pragma once
#include "methods/map_method.hpp"

namespace shadowlab {

// Cube shadow maps: six 90° perspective maps from a spot or point light, one along each world
// axis, in a 3 x 2 atlas; a point reads the face of the major axis of its direction from the light.
// A directional light takes the focused map as a named fallback.
ShadowSetup compute_cube(const ShadowInputs& inputs, const Settings& settings, Trace* trace);
std::vector<SettingSpec> cube_settings();

}  // namespace shadowlab
