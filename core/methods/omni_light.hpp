#pragma once
// What the omnidirectional maps (dpsm, cube) share: the distances their depth spans, the named
// fallback for a directional light (no position to look out from), and the step that draws the
// range around the light.
#include <string>

#include "methods/map_method.hpp"

namespace shadowlab {

// The light's range when the scene gives one; else from the scene: far just beyond the farthest
// corner of its bounds (every point the light can reach), near just short of the nearest caster's
// box (nothing nearer casts; depth precision then starts where the casters do), at least far / 1e4
// (a light inside a caster's box but outside the caster: the perspective faces need near > 0).
LightRange omni_range(const ShadowInputs& inputs);

// True for a spot or point light. For a directional light `setup` gets the focused map instead,
// with the fallback named.
bool omni_or_focused(const std::string& method, const ShadowInputs& inputs, const Settings& settings,
                     ShadowSetup& setup, Trace* trace);

// Step `range`: the near and far distances as circles around the light in its three axis planes.
void record_range(Trace& trace, const Light& light, const LightRange& range, bool from_scene);

}  // namespace shadowlab
