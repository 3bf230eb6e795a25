#pragma once
#include <vector>

#include "methods/map_method.hpp"

namespace shadowlab {

ShadowSetup compute_logpsm(const ShadowInputs& inputs, const Settings& settings, Trace* trace);
// logpsm's settings, with their ranges and defaults.
std::vector<SettingSpec> logpsm_settings();

// Below this log(far / near) the log warp is dropped for the perspective alone (the note log_range_short).
inline constexpr double kMinLogRange = 0.1;

}  // namespace shadowlab
