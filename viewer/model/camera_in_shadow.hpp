#pragma once
// A camera standing inside a caster's shadow volume: where z-pass stencil counts go wrong (the
// eye ray starts inside the volume) and z-fail still holds (Everitt and Kilgard 2002, section 4).
#include <optional>

#include "scene/scene.hpp"

namespace shadowlab {

// The scene's camera moved into a caster's shadow, still looking at its target (or along its view
// direction when the target lies straight below or above): on the ray away from the light through
// a point near the top of the caster (inside it), a quarter of the caster's diagonal past where the
// ray leaves its bounds. Of all casters (planes aside), the spot standing highest; nullopt when no
// spot is clear of every object and above the ground.
std::optional<Camera> camera_in_shadow(const Scene& scene);

}  // namespace shadowlab
