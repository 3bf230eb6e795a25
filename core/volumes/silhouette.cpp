#include "volumes/silhouette.hpp"

#include <cstdlib>
#include <map>

#include "geometry/homogeneous_plane.hpp"

namespace shadowlab {

// Relative to the triangle's first corner: the plane's determinants then multiply the triangle's
// own small numbers, and a scene far from the origin keeps its signs.
double light_facing(const std::array<glm::dvec3, 3>& c, const glm::dvec4& light) {
    const glm::dvec4 local_light = light - glm::dvec4(c[0] * light.w, 0.0);
    return glm::dot(
        plane_through(glm::dvec4(0.0, 0.0, 0.0, 1.0), glm::dvec4(c[1] - c[0], 1.0), glm::dvec4(c[2] - c[0], 1.0)),
        local_light);
}

namespace {

std::array<glm::dvec3, 3> corners(const WorldTriangles& triangles, int t) {
    const auto& i = triangles.triangles[t];
    return {triangles.vertices[i[0]], triangles.vertices[i[1]], triangles.vertices[i[2]]};
}

OrientedTriangle reversed(const OrientedTriangle& t) { return {{t.corners[0], t.corners[2], t.corners[1]}, t.object}; }

// How each of the object's triangles takes part: +1 as wound, -1 reversed, 0 not at all.
std::map<int, int> casting_signs(const ObjectTopology& object, const WorldTriangles& triangles, const glm::dvec4& light,
                                 Silhouette& out) {
    std::map<int, int> sign;
    for (int t : object.triangles) {
        const OrientedTriangle triangle{corners(triangles, t), object.object};
        const double facing = light_facing(triangle.corners, light);
        sign[t] = facing > 0.0 ? 1 : (facing < 0.0 && !object.closed() ? -1 : 0);
        if (sign[t] != 0) out.casting.push_back(sign[t] > 0 ? triangle : reversed(triangle));
        if (object.closed() && facing < 0.0)
            out.back_cap.push_back(triangle);  // Everitt-Kilgard: back faces at infinity
        if (!object.closed() && sign[t] != 0) out.back_cap.push_back(reversed(out.casting.back()));
    }
    return sign;
}

}  // namespace

Silhouette find_silhouette(const std::vector<ObjectTopology>& topology, const WorldTriangles& triangles,
                           const Light& light) {
    Silhouette out;
    for (const ObjectTopology& object : topology) {
        const std::map<int, int> sign = casting_signs(object, triangles, light.homogeneous(), out);
        for (const MeshEdge& e : object.edges) {
            int multiplicity = 0;
            for (const EdgeUse& use : e.uses) multiplicity += use.direction * sign.at(use.triangle);
            if (multiplicity > 0) out.edges.push_back({e.a, e.b, multiplicity, object.object});
            if (multiplicity < 0) out.edges.push_back({e.b, e.a, -multiplicity, object.object});
        }
    }
    return out;
}

}  // namespace shadowlab
