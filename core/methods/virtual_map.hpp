#pragma once
// Virtual shadow maps for a directional light, as Unreal Engine 5 draws sun shadows: clipmap levels
// about the camera (methods/clipmap.hpp), the pages the camera's depth image needs marked and given
// physical slots up to a budget (methods/page_marking.hpp), each resident page a map of the setup
// drawn into its slot, a point reading the finest resident page that holds it (maps/page_table.hpp).
#include <optional>

#include "methods/map_method.hpp"

namespace shadowlab {

ShadowSetup compute_virtual(const ShadowInputs& inputs, const Settings& settings, Trace* trace);
std::vector<SettingSpec> virtual_settings();
// Always: the pages are marked from the camera's depth image (ShadowInputs::seen_receivers).
bool virtual_reads_visible_depths(const Settings& settings);
// Texels `factor` times finer: the resolution bias lowered by whole levels, log2 of the factor
// rounded up (at least one), down to its least; nullopt there.
std::optional<SettingsChange> virtual_finer_texels(const Settings& settings, double factor);

}  // namespace shadowlab
