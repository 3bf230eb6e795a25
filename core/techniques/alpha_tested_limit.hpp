#pragma once
// The limit every geometric technique shares: its polygons (shadow volumes, flattened casters) are
// the casters' triangles whole, so an alpha-tested caster casts through its holes too.
#include <optional>
#include <vector>

#include "notes/note.hpp"
#include "scene/tessellation.hpp"

namespace shadowlab {

// The note alpha_tested_whole counting the alpha-tested caster triangles, or nullopt when there is none.
std::optional<Note> alpha_tested_limit(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object);

}  // namespace shadowlab
