#pragma once
#include "methods/map_method.hpp"

namespace shadowlab {

// Cascaded (parallel-split) shadow maps: the view's depth range split in `count` slices, one map per
// slice in a tile of one atlas, each point looked up in its slice's map (or the first tile that holds
// it). Directional lights; a spot or point light takes the focused map as a named fallback.
ShadowSetup compute_cascades(const ShadowInputs& inputs, const Settings& settings, Trace* trace);
// cascades' settings, with their ranges and defaults.
std::vector<SettingSpec> cascades_settings();
// bounds = visible: the splits span the receivers the camera's depth image shows (visible_depths).
bool cascades_read_visible_depths(const Settings& settings);

}  // namespace shadowlab
