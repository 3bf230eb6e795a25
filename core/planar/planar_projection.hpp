#pragma once
// Planar projection shadows (Blinn 1988; seed 001, "The Projection Matrix"): the casters
// flattened onto a receiving plane along the light's rays by one 4x4 matrix.
#include <optional>
#include <vector>
#include <glm/glm.hpp>

#include "geometry/homogeneous_clip.hpp"
#include "scene/scene.hpp"
#include "scene/tessellation.hpp"

namespace shadowlab {

// M = (P . L) I - L P^T for the plane P = (n, d) (points with n . x + d = 0) and the light as a
// homogeneous point L ((position, 1), or (-direction, 0) for a directional light). M X lies on
// the plane and on the line through L and X; the w of M X is (P . L) X.w - L.w (P . X), which is
// <= 0 for a point as far from the plane as the light or farther. The seed prints this matrix
// row by row (its second diagonal entry should read n . l + d - n_y l_y).
glm::dmat4 planar_projection_matrix(const glm::dvec4& plane, const glm::dvec4& light);

struct ReceiverPlane {
    int object = -1;        // a `receives` plane object
    glm::dvec4 plane;       // (n, d), turned so that the light is on its positive side
    glm::dmat4 projection;  // planar_projection_matrix(plane, light)
};

// The plane of a plane object (its local +y side), turned toward the light; nullopt when the
// light lies in it.
std::optional<ReceiverPlane> receiver_plane(const Scene& scene, int object);

struct FlattenedCasters {
    std::vector<HomogeneousPolygon> polygons;  // on the plane, w = 1
    int below_plane = 0;                       // caster triangles reaching below it (by more than 1e-3 of
                                               // their object's size): false shadows
    int beyond_light = 0;                      // caster triangles reaching beyond the light: clipped at w = 0
};

// Every caster triangle (but the receiver's own) through the matrix, clipped first to the part
// with w > 0 (between the light's plane and the receiver, or below it), then divided.
FlattenedCasters flatten_casters(const Scene& scene, const WorldTriangles& triangles, const ReceiverPlane& receiver);

// Does the point of the plane lie in the flattened convex polygon (either winding, edges included)?
bool covers(const HomogeneousPolygon& flattened, const glm::dvec3& normal, const glm::dvec3& p);

}  // namespace shadowlab
