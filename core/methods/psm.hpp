#pragma once
#include "methods/map_method.hpp"

namespace shadowlab {

// The intersection body's kernel; the depth bias is the other maps' (slope-scaled x1). A smaller
// scale (0.25 was PSM's default once, found by `sweep --bias` on the default and grazing-sun scenes,
// where PSM's false light dominates and it loses to the focused map whatever its bias) leaves less
// than the half texel a hard lookup's sample may lie from the receiver (x0.5 at least, the more for
// faces near edge-on to the light, whose tan θ the slope-scaled bias clamps at 10): false shadow on
// every lone mesh under the default sun (Blender's default cube 2.28% against the focused map's
// 0.009%, 2CylinderEngine 7.77% against 0.147%).
std::vector<SettingSpec> psm_settings();

ShadowSetup compute_psm(const ShadowInputs& inputs, const Settings& settings, Trace* trace);

}  // namespace shadowlab
