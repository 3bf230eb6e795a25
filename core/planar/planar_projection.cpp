#include "planar/planar_projection.hpp"

#include <algorithm>
#include <cmath>

#include "math/matrix.hpp"

namespace shadowlab {

glm::dmat4 planar_projection_matrix(const glm::dvec4& plane, const glm::dvec4& light) {
    return glm::dot(plane, light) * glm::dmat4(1.0) - glm::outerProduct(light, plane);  // column vectors: L P^T
}

std::optional<ReceiverPlane> receiver_plane(const Scene& scene, int object) {
    const SceneObject& o = scene.objects[object];
    const glm::dmat4 model = o.model_matrix();
    const glm::dvec3 normal = glm::normalize(glm::transpose(glm::inverse(glm::dmat3(model))) * glm::dvec3(0, 1, 0));
    glm::dvec4 plane(normal, -glm::dot(normal, glm::dvec3(model[3])));
    const glm::dvec4 light = scene.light.homogeneous();
    const double side = glm::dot(plane, light);
    if (side == 0.0) return std::nullopt;
    if (side < 0.0) plane = -plane;
    return ReceiverPlane{object, plane, planar_projection_matrix(plane, light)};
}

namespace {

// Below the plane by less than this share of the scene's largest coordinate (the reference's own
// surface offset) is resting on it.
constexpr double kRelativeDepth = 1e-5;

double largest_coordinate(const std::vector<glm::dvec3>& vertices) {
    double largest = 0.0;
    for (const glm::dvec3& v : vertices) largest = std::max({largest, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    return largest;
}

}  // namespace

FlattenedCasters flatten_casters(const Scene& scene, const WorldTriangles& triangles, const ReceiverPlane& r) {
    FlattenedCasters out;
    const glm::dvec4 w_row = row(r.projection, 3);
    const double resting = kRelativeDepth * largest_coordinate(triangles.vertices) * glm::length(glm::dvec3(r.plane));
    for (std::size_t i = 0; i < triangles.triangles.size(); ++i) {
        const int object = triangles.object[i];
        if (object == r.object || !scene.objects[object].casts) continue;
        HomogeneousPolygon polygon;
        double largest_w = 0.0;
        bool below = false, beyond = false;
        for (int k : triangles.triangles[i]) {
            const glm::dvec4 v(triangles.vertices[k], 1.0);
            polygon.push_back(v);
            largest_w = std::max(largest_w, std::abs(glm::dot(w_row, v)));
            beyond |= glm::dot(w_row, v) <= 0.0;
            below |= glm::dot(r.plane, v) < -resting;
        }
        out.below_plane += below;
        out.beyond_light += beyond;
        polygon = clip(polygon, {w_row, 1e-9 * largest_w});  // keep w > 0: a finite projection
        if (polygon.size() < 3) continue;
        for (glm::dvec4& v : polygon) v = glm::dvec4(transform_point(r.projection, glm::dvec3(v)), 1.0);
        out.polygons.push_back(std::move(polygon));
    }
    return out;
}

bool covers(const HomogeneousPolygon& flattened, const glm::dvec3& normal, const glm::dvec3& p) {
    bool positive = false, negative = false;
    for (std::size_t i = 0; i < flattened.size(); ++i) {
        const glm::dvec3 a(flattened[i]), b(flattened[(i + 1) % flattened.size()]);
        const double side = glm::dot(glm::cross(b - a, p - a), normal);
        positive |= side > 0.0;
        negative |= side < 0.0;
    }
    return !(positive && negative);
}

}  // namespace shadowlab
