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

// A caster below the plane by less than this share of its own size rests on it (a scene file's
// rounded position, not a caster reaching through): a size of its own, so that the verdict holds
// wherever the scene stands and whatever its scale.
constexpr double kRelativeDepth = 1e-3;

}  // namespace

// The casters are flattened in coordinates centred on the receiver: M multiplies coordinates by
// P . L, so an error in P . L (a distance) would grow with their size far from the origin.
FlattenedCasters flatten_casters(const Scene& scene, const WorldTriangles& triangles, const ReceiverPlane& r) {
    FlattenedCasters out;
    const glm::dvec3 origin = scene.objects[r.object].position;
    const glm::dvec4 local_plane(glm::dvec3(r.plane), r.plane.w + glm::dot(glm::dvec3(r.plane), origin));
    const glm::dvec4 light = scene.light.homogeneous();
    const glm::dmat4 local_projection =
        planar_projection_matrix(local_plane, light - glm::dvec4(origin * light.w, 0.0));
    const glm::dvec4 w_row = row(local_projection, 3);
    const double plane_scale = glm::length(glm::dvec3(r.plane));  // plane . v is a distance times this
    std::vector<double> resting(scene.objects.size());            // per object: how far below still rests
    for (std::size_t o = 0; o < resting.size(); ++o)
        resting[o] = kRelativeDepth * scene.objects[o].world_bounds().diagonal() * plane_scale;
    for (std::size_t i = 0; i < triangles.triangles.size(); ++i) {
        const int object = triangles.object[i];
        if (object == r.object || !scene.objects[object].casts) continue;
        HomogeneousPolygon polygon;
        double largest_w = 0.0;
        bool below = false, beyond = false;
        for (int k : triangles.triangles[i]) {
            const glm::dvec4 v(triangles.vertices[k] - origin, 1.0);
            polygon.push_back(v);
            largest_w = std::max(largest_w, std::abs(glm::dot(w_row, v)));
            beyond |= glm::dot(w_row, v) <= 0.0;
            below |= glm::dot(local_plane, v) < -resting[object];
        }
        out.below_plane += below;
        out.beyond_light += beyond;
        polygon = clip(polygon, {w_row, 1e-9 * largest_w});  // keep w > 0: a finite projection
        if (polygon.size() < 3) continue;
        for (glm::dvec4& v : polygon) v = glm::dvec4(transform_point(local_projection, glm::dvec3(v)) + origin, 1.0);
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
