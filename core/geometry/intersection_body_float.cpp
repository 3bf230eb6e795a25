// The intersection body with our own floating-point plane clipper. The extrusion of V toward the
// light is itself an intersection of half-spaces: V's faces that turn away from the light, plus
// one plane through each silhouette edge and the light. So B = S clipped by those planes.
#include <vector>

#include "geometry/intersection_body.hpp"

namespace shadowlab {
namespace {

// Distances under this count as zero: a share of the scene's size, plus the rounding of coordinates
// as far from the origin as its centre (a few hundred double ulps there), so that a small scene far
// away keeps its shape.
double clip_tolerance(const Aabb& s) { return 1e-10 * s.diagonal() + 1e-13 * glm::length(s.center()); }

bool cuts(const ConvexPolyhedron& poly, const Plane& plane, double tolerance) {
    for (const glm::dvec3& v : poly.vertices)
        if (plane.signed_distance(v) > tolerance) return true;
    return false;
}

ConvexPolyhedron clipped(ConvexPolyhedron poly, const std::vector<Plane>& planes, double tolerance) {
    for (const Plane& plane : planes) {
        if (!cuts(poly, plane, tolerance)) continue;  // redundant plane: no copy
        poly = clip(poly, plane, tolerance);
        if (poly.empty()) break;
    }
    return poly;
}

// The plane through edge a-b that contains the light (a point, or a direction when w = 0),
// oriented so that `inner` lies inside. Nullopt when the edge points at the light.
std::optional<Plane> silhouette_plane(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec4& light,
                                      const glm::dvec3& inner) {
    const glm::dvec3 toward_light = light.w == 0.0 ? glm::dvec3(light) : glm::dvec3(light) - a;
    const glm::dvec3 n = glm::cross(b - a, toward_light);
    const double length = glm::length(n);
    if (!(length > 1e-12 * glm::length(b - a) * glm::length(toward_light))) return std::nullopt;
    Plane plane = Plane::through(a, n / length);
    if (plane.signed_distance(inner) > 0.0) plane = Plane::through(a, -plane.normal);
    return plane;
}

// Bounding planes of hull(V ∪ light): faces of V turned away from the light, and silhouette planes.
std::vector<Plane> extrusion_planes(const ConvexPolyhedron& v, const glm::dvec4& light, double tolerance) {
    // A face looks at the light when the light is outside its plane: a distance for a point light,
    // a cosine (unitless) for a direction.
    const double facing_tolerance = light.w == 0.0 ? 1e-12 : tolerance;
    std::vector<bool> faces_light(v.faces.size());
    for (size_t f = 0; f < v.faces.size(); ++f)
        faces_light[f] = v.faces[f].plane.signed_distance(light) > facing_tolerance;

    std::vector<Plane> planes;
    std::vector<int> face_of_edge(v.vertices.size() * v.vertices.size(), -1);  // directed edge a->b
    const size_t n = v.vertices.size();
    for (size_t f = 0; f < v.faces.size(); ++f) {
        if (!faces_light[f]) planes.push_back(v.faces[f].plane);
        const auto& loop = v.faces[f].loop;
        for (size_t k = 0; k < loop.size(); ++k) face_of_edge[loop[k] * n + loop[(k + 1) % loop.size()]] = int(f);
    }
    // A silhouette edge: its face looks at the light, its twin's face does not.
    const glm::dvec3 inner = v.centroid();
    for (size_t a = 0; a < n; ++a)
        for (size_t b = 0; b < n; ++b) {
            const int f = face_of_edge[a * n + b], g = face_of_edge[b * n + a];
            if (f < 0 || g < 0 || !faces_light[f] || faces_light[g]) continue;
            if (auto plane = silhouette_plane(v.vertices[a], v.vertices[b], light, inner)) planes.push_back(*plane);
        }
    return planes;
}

}  // namespace

IntersectionBody intersection_body_float(const BodyInput& input) {
    const double tolerance = clip_tolerance(input.scene_bounds);
    const ConvexPolyhedron scene = ConvexPolyhedron::box(input.scene_bounds);
    IntersectionBody out;
    out.visible = clipped(scene, {input.frustum.planes.begin(), input.frustum.planes.end()}, tolerance);
    if (out.visible.empty()) return {};
    out.body = clipped(scene, extrusion_planes(out.visible, input.light, tolerance), tolerance);
    return out;
}

}  // namespace shadowlab
