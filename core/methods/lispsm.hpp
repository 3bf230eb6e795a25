#pragma once
#include "methods/map_method.hpp"

namespace shadowlab {

ShadowSetup compute_lispsm(const ShadowInputs& inputs, const Settings& settings, Trace* trace);
// lispsm's settings, with their ranges and defaults.
std::vector<SettingSpec> lispsm_settings();


// The warp frustum's near distance n for the eye range [z_n, z_f] and angle γ between view and
// light, with Lloyd's η: the warp's far/near ratio is (z_f / z_n)^((1 + η) / 2), so η = -1 gives
// no warp (n = ∞), η = 0 LiSPSM's n_opt = (z_n + sqrt(z_n z_f)) / sin γ, η = 1 PSM's n = z_n / sin γ.
double lispsm_n(double z_n, double z_f, double sin_gamma, double eta);

}  // namespace shadowlab
