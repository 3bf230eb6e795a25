#pragma once
#include "geometry/intersection_body.hpp"
#include "methods/method.hpp"

namespace shadowlab {

ShadowSetup compute_focused(const ShadowInputs& inputs, const Settings& settings, Trace* trace);

// The `kernel` setting, shared by every method that builds the intersection body.
const SettingSpec& body_kernel_setting();
// The body for these inputs with the chosen kernel, recorded as the steps frustum, visible, body.
IntersectionBody focus_body(const ShadowInputs& inputs, const Settings& settings, Trace* trace);

}  // namespace shadowlab
