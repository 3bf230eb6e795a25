#pragma once
// The intersection body of Wimmer and Scherzer: the convex set of points that can cast a shadow
// into the visible part of the scene,
//     B = hull(V ∪ light) ∩ S,   V = view frustum ∩ S,   S = scene bounds,
// where "∪ light" extrudes V toward the light (to infinity for a directional light).
#include <optional>
#include <string>
#include <glm/glm.hpp>

#include "geometry/aabb.hpp"
#include "geometry/convex_polyhedron.hpp"
#include "geometry/frustum.hpp"

namespace shadowlab {

// How the body is computed: our own floating-point plane clipper, or CGAL with the inexact or the
// exact constructions kernel. A speed / exactness trade offered to the user.
enum class BodyKernel { float_clipper, epick, epeck };

const char* to_string(BodyKernel kernel);  // "float", "epick", "epeck"
std::optional<BodyKernel> body_kernel_from_string(const std::string& name);

struct BodyInput {
    Frustum frustum;
    Aabb scene_bounds;
    // The light as a homogeneous point: (position, 1) for point and spot lights, and
    // (-direction, 0), the point at infinity the light comes from, for a directional light.
    glm::dvec4 light;
};

struct IntersectionBody {
    ConvexPolyhedron visible;  // V = frustum ∩ S (empty when nothing of the scene is visible)
    ConvexPolyhedron body;     // B (empty when V is)
};

IntersectionBody intersection_body(const BodyInput& input, BodyKernel kernel);

// The floating-point clipper path (intersection_body_float.cpp).
IntersectionBody intersection_body_float(const BodyInput& input);
// The CGAL paths (intersection_body_cgal.cpp; CGAL stays inside that file).
IntersectionBody intersection_body_cgal(const BodyInput& input, bool exact);

}  // namespace shadowlab
