#pragma once
#include "methods/map_method.hpp"

namespace shadowlab {

ShadowSetup compute_psm(const ShadowInputs& inputs, const Settings& settings, Trace* trace);

}  // namespace shadowlab
