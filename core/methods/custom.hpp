#pragma once
// Bring your own matrices: an engine's light view-projections, read from a file as the engine
// writes them, shown and measured as ShadowLab's own maps are.
#include "methods/map_method.hpp"

namespace shadowlab {

// The maps of the `matrices` file under the named conventions, with a coverage report as notes
// (methods/map_coverage.hpp); with no file, the focused map as a named fallback.
ShadowSetup compute_custom(const ShadowInputs& inputs, const Settings& settings, Trace* trace);
std::vector<SettingSpec> custom_settings();

}  // namespace shadowlab
