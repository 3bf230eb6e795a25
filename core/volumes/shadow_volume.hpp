#pragma once
// The shadow volume as polygons a GPU would draw into the stencil buffer (Everitt and Kilgard
// 2002): each silhouette edge extruded away from the light to infinity (w = 0), and for z-fail the
// caps that close it, the front cap on the casters and the back cap at infinity.
#include <vector>
#include <glm/glm.hpp>

#include "geometry/homogeneous_clip.hpp"
#include "scene/light.hpp"
#include "volumes/silhouette.hpp"

namespace shadowlab {

// A convex polygon of the volume, counter-clockwise seen from outside the volume; w = 0 marks a
// vertex at infinity. A GPU draws it `multiplicity` times.
struct VolumePolygon {
    HomogeneousPolygon vertices;
    int multiplicity = 1;
    int object = -1;
};

struct ShadowVolume {
    std::vector<VolumePolygon> quads;      // per silhouette edge a -> b: (b, a, a at infinity, b at infinity)
    std::vector<VolumePolygon> front_cap;  // the casting triangles, as they are (w = 1)
    std::vector<VolumePolygon> back_cap;   // projected to infinity; none for a directional light
};

// p pushed away from the light to infinity: (p - light position, 0), or (light direction, 0) for
// a directional light (every point goes to the same one).
glm::dvec4 at_infinity(const glm::dvec3& p, const Light& light);

ShadowVolume extrude_volume(const Silhouette& silhouette, const Light& light);

}  // namespace shadowlab
