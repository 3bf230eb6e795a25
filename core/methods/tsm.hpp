#pragma once
#include "methods/method.hpp"

namespace shadowlab {

ShadowSetup compute_tsm(const ShadowInputs& inputs, const Settings& settings, Trace* trace);

}  // namespace shadowlab
