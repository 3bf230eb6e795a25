#include "volumes/shadow_volume.hpp"

namespace shadowlab {

glm::dvec4 at_infinity(const glm::dvec3& p, const Light& light) {
    const glm::dvec4 l = light.homogeneous();
    return {l.w * p - glm::dvec3(l), 0.0};
}

namespace {

VolumePolygon finite(const OrientedTriangle& t) {
    return {{glm::dvec4(t.corners[0], 1.0), glm::dvec4(t.corners[1], 1.0), glm::dvec4(t.corners[2], 1.0)}, 1, t.object};
}

}  // namespace

ShadowVolume extrude_volume(const Silhouette& s, const Light& light) {
    ShadowVolume v;
    for (const SilhouetteEdge& e : s.edges)  // the side of the volume runs b -> a, against the cap's a -> b
        v.quads.push_back(
            {{glm::dvec4(e.b, 1.0), glm::dvec4(e.a, 1.0), at_infinity(e.a, light), at_infinity(e.b, light)},
             e.multiplicity,
             e.object});
    for (const OrientedTriangle& t : s.casting) v.front_cap.push_back(finite(t));
    if (light.is_directional()) return v;  // the back cap would collapse to the point (direction, 0)
    for (const OrientedTriangle& t : s.back_cap)
        v.back_cap.push_back(
            {{at_infinity(t.corners[0], light), at_infinity(t.corners[1], light), at_infinity(t.corners[2], light)},
             1,
             t.object});
    return v;
}

}  // namespace shadowlab
