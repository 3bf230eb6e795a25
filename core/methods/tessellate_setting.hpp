#pragma once
// The setting of every method whose map bends straight edges (a paraboloid's, a log perspective's):
// how far a caster's edge may bow from the chord a GPU draws before it is split
// (ShadowMap::max_sagitta_texels, raster/paraboloid_edges.hpp).
#include <string>

#include "methods/settings.hpp"

namespace shadowlab {

inline SettingSpec tessellate_setting(const std::string& default_texels) {
    return {.name = "tessellate",
            .description = "split casters until no edge bows more than this many texels from its chord; 0: as given",
            .default_value = default_texels,
            .min = 0.0,
            .max = 64.0};
}

}  // namespace shadowlab
