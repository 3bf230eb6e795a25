#pragma once
#include "methods/map_method.hpp"

namespace shadowlab {

ShadowSetup compute_xpsm(const ShadowInputs& inputs, const Settings& settings, Trace* trace);
// xpsm's settings, with their ranges and defaults.
std::vector<SettingSpec> xpsm_settings();

}  // namespace shadowlab
