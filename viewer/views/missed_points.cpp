// Where the map misses what the camera sees: the visible points of a coarse camera image (the exact
// reference's, traced once per size) that no map of the setup holds in its [0,1]^3. A point outside
// gets no shadow from the map, whatever stands between it and the light.
#include <algorithm>
#include <cmath>

#include "maps/map_lookup.hpp"
#include "views/space_parts.hpp"

namespace shadowlab {
namespace {

constexpr int kMarksWidth = 96;  // image pixels across: enough to show where, cheap to trace
constexpr double kTolerance = 1e-6;

bool covered(const ShadowSetup& setup, const glm::dvec3& p) {
    const std::optional<MapPoint> at = map_point(setup, p);
    return at && glm::all(glm::greaterThanEqual(at->uvz(), glm::dvec3(-kTolerance))) &&
           glm::all(glm::lessThanEqual(at->uvz(), glm::dvec3(1.0 + kTolerance)));
}

}  // namespace

MissedPoints visible_points_missed(const Inspection& in) {
    const int height = std::max(1, static_cast<int>(std::lround(kMarksWidth / in.scene.camera.aspect)));
    const ReferenceImage& reference = in.reference(kMarksWidth, height);
    MissedPoints missed;
    for (size_t i = 0; i < reference.visible.size(); ++i)
        if (reference.visible[i] && !covered(in.setup, reference.position[i]))
            (reference.lit[i] ? missed.lit : missed.in_shadow).push_back(reference.position[i]);
    return missed;
}

}  // namespace shadowlab
