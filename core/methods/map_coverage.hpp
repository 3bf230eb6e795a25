#pragma once
// What a setup's maps cover of what the view needs. ShadowLab's own methods fit their maps to the
// view; an engine's matrices (the custom method) were fitted by the engine, so this names what they
// miss and what they waste: visible receivers outside every map, casters cut by a near plane,
// texels that see nothing of the view.
#include <vector>
#include <glm/glm.hpp>

#include "maps/shadow_map.hpp"
#include "methods/shadow_inputs.hpp"
#include "notes/note.hpp"

namespace shadowlab {

struct MapCoverage {
    std::vector<glm::dvec3> receiver_points;  // the vertices of each receiver box cut to the view frustum
    std::vector<glm::dvec3> missed_points;    // those no map's [0,1]^3 holds
    std::vector<Aabb> missed_receivers;       // the receiver boxes they lie on
    std::vector<glm::dvec3> clipped_points;   // caster points in a map's (u, v) square with d < 0
    int clipped_casters = 0;                  // the caster boxes they lie on
    // The share of the tiles' area (texels, weighted by tile) whose (u, v) sees no point of
    // V = frustum ∩ scene bounds.
    double texels_outside_view = 0.0;
};

// Linear maps only (an engine's light view-projections).
MapCoverage map_coverage(const ShadowInputs& inputs, const ShadowSetup& setup);

// The named notes: missed receivers, clipped casters, and more than kWastedShareNoted of the texels
// outside the view; none when the maps cover what the view needs.
inline constexpr double kWastedShareNoted = 0.5;
std::vector<Note> coverage_notes(const MapCoverage& coverage);

}  // namespace shadowlab
