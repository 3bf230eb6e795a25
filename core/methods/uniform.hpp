#pragma once
#include "methods/map_method.hpp"

namespace shadowlab {

ShadowSetup compute_uniform(const ShadowInputs& inputs, const Settings& settings, Trace* trace);
// The uniform fit appended to an existing setup (used by methods that fall back to it).
void fit_uniform(const ShadowInputs& inputs, ShadowSetup& setup, Trace* trace);

}  // namespace shadowlab
