#pragma once
#include "methods/map_method.hpp"

namespace shadowlab {

// The intersection body's kernel, and a smaller slope-scaled bias than the other maps': a PSM texel
// is long across the light where it is narrow along the view, and the slope-scaled bias sizes itself
// by the texel's longest extent; `sweep --bias` finds PSM's least error near 0.1-0.2 times it on the
// default and grazing-sun scenes, where 1 doubles the false light.
std::vector<SettingSpec> psm_settings();

ShadowSetup compute_psm(const ShadowInputs& inputs, const Settings& settings, Trace* trace);

}  // namespace shadowlab
