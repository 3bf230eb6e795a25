#pragma once
#include "methods/map_method.hpp"

namespace shadowlab {

// Dual-paraboloid shadow maps (Brabec, Annen and Seidel 2002; seed 002): the sphere of directions
// around a spot or point light as two hemispheres, each mapped by a paraboloid onto a disc in its
// tile of one atlas; a point reads the hemisphere on whose side it lies. A directional light takes
// the focused map as a named fallback.
ShadowSetup compute_dpsm(const ShadowInputs& inputs, const Settings& settings, Trace* trace);
std::vector<SettingSpec> dpsm_settings();

}  // namespace shadowlab
