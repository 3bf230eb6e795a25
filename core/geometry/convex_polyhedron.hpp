#pragma once
// A closed convex polyhedron: shared vertices and faces as counter-clockwise loops (seen from
// outside), each face remembering the plane it lies on.
#include <vector>
#include <glm/glm.hpp>

#include "geometry/aabb.hpp"
#include "geometry/plane.hpp"

namespace shadowlab {

struct PolyFace {
    std::vector<int> loop;  // indices into vertices, counter-clockwise seen from outside
    Plane plane;            // outward normal
};

struct ConvexPolyhedron {
    std::vector<glm::dvec3> vertices;
    std::vector<PolyFace> faces;

    bool empty() const { return faces.size() < 4; }
    Aabb bounds() const;
    double volume() const;
    glm::dvec3 centroid() const;  // mean of the vertices

    static ConvexPolyhedron box(const Aabb& box);
};

// Keeps the part of `poly` on the inside of `plane` (n.x + offset <= 0) and closes the cut with a
// cap face on `plane`. `tolerance` is the distance under which a vertex counts as on the plane.
ConvexPolyhedron clip(const ConvexPolyhedron& poly, const Plane& plane, double tolerance);

// Every directed edge has its twin in another face and no face has fewer than 3 vertices.
bool is_closed(const ConvexPolyhedron& poly);
// Every vertex lies inside every face plane, within `tolerance` (a distance).
bool is_convex(const ConvexPolyhedron& poly, double tolerance);

}  // namespace shadowlab
