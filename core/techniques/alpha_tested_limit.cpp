#include "techniques/alpha_tested_limit.hpp"

#include <string>

namespace shadowlab {

std::optional<Note> alpha_tested_limit(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object) {
    std::size_t tested = 0;
    for (std::size_t i = 0; i < triangles.alpha.size(); ++i)
        tested += triangles.alpha[i].test && casts_per_object.at(triangles.object[i]);
    if (tested == 0) return std::nullopt;
    return Note{NoteKind::alpha_tested_whole,
                std::to_string(tested) + " alpha-tested caster triangles cast whole, holes and all"};
}

}  // namespace shadowlab
