#pragma once
// The casters as seen from the light: which triangles face it, and the silhouette edges between
// them and the rest, the edges a shadow volume is extruded from.
#include <array>
#include <vector>
#include <glm/glm.hpp>

#include "scene/light.hpp"
#include "scene/tessellation.hpp"
#include "volumes/edge_topology.hpp"

namespace shadowlab {

struct OrientedTriangle {
    std::array<glm::dvec3, 3> corners;  // counter-clockwise seen from the side it faces
    int object = -1;
};

// An edge of the casting triangles' boundary, running a -> b as they run along it; an edge of
// several boundaries (a non-manifold mesh) has them all in its multiplicity.
struct SilhouetteEdge {
    glm::dvec3 a, b;
    int multiplicity = 1;
    int object = -1;
};

struct Silhouette {
    // The triangles whose volumes are summed: of a closed mesh those facing the light; of an open
    // or non-manifold one every triangle not edge-on, turned to face the light (two-sided).
    std::vector<OrientedTriangle> casting;
    // Projected to infinity as they are, they close the volume: a closed mesh's triangles turned
    // from the light; for an open mesh its casting triangles reversed.
    std::vector<OrientedTriangle> back_cap;
    std::vector<SilhouetteEdge> edges;
};

// > 0 when the triangle's front side faces the light (the light is a homogeneous point, w = 0 for
// a directional light).
double light_facing(const std::array<glm::dvec3, 3>& corners, const glm::dvec4& light);

// Per edge, the multiplicity is the sum over its casting triangles of +1 or -1 as they run along
// it; the silhouette is the edges where that sum is not 0 (McGuire's generalized silhouettes).
Silhouette find_silhouette(const std::vector<ObjectTopology>& topology, const WorldTriangles& triangles,
                           const Light& light);

}  // namespace shadowlab
