// The projection kinds: one case each. Adding a kind: its files, its enumerator in Projection and one
// case here (see docs/ARCHITECTURE.md, "Adding a projection kind"); a kind left out is a compile error
// (-Wswitch, warnings as errors).
#include <stdexcept>
#include <string>

#include "maps/linear_projection.hpp"
#include "maps/log_perspective_projection.hpp"
#include "maps/paraboloid_projection.hpp"

namespace shadowlab {
namespace {

// nullptr past the last enumerator.
const ProjectionKind* registered(Projection projection) {
    switch (projection) {
        case Projection::linear: return &linear_projection;
        case Projection::paraboloid: return &paraboloid_projection;
        case Projection::cube_face: return &cube_face_projection;
        case Projection::log_perspective: return &log_perspective_projection;
    }
    return nullptr;
}

}  // namespace

const ProjectionKind& projection_kind(Projection projection) {
    if (const ProjectionKind* kind = registered(projection)) return *kind;
    throw std::invalid_argument("projection kind " + std::to_string(int(projection)) +
                                " has no descriptor in maps/projection_kinds.cpp");
}

std::vector<Projection> projection_kinds() {
    std::vector<Projection> kinds;
    for (int k = 0; registered(Projection(k)); ++k) kinds.push_back(Projection(k));
    return kinds;
}

const char* to_string(Projection projection) { return projection_kind(projection).name; }

}  // namespace shadowlab
