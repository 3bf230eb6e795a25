#pragma once
#include "methods/map_method.hpp"

namespace shadowlab {

ShadowSetup compute_tsm(const ShadowInputs& inputs, const Settings& settings, Trace* trace);
// tsm's settings, with their ranges and defaults.
std::vector<SettingSpec> tsm_settings();

}  // namespace shadowlab
