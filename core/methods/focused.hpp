#pragma once
#include <optional>

#include "geometry/intersection_body.hpp"
#include "methods/map_method.hpp"

namespace shadowlab {

ShadowSetup compute_focused(const ShadowInputs& inputs, const Settings& settings, Trace* trace);

// The body, or nullopt when it is empty and `setup` got the uniform map as a named fallback.
std::optional<IntersectionBody> body_or_uniform(const ShadowInputs& inputs, const Settings& settings,
                                                ShadowSetup& setup, Trace* trace);
// The orthographic (or, for spot and point lights, perspective) fit to a non-empty body.
void fit_focused(const ShadowInputs& inputs, const IntersectionBody& body, ShadowSetup& setup, Trace* trace);

// The `kernel` setting, shared by every method that builds the intersection body.
const SettingSpec& body_kernel_setting();
// The body for these inputs with the chosen kernel, recorded as the steps frustum, visible, body.
IntersectionBody focus_body(const ShadowInputs& inputs, const Settings& settings, Trace* trace);

}  // namespace shadowlab
