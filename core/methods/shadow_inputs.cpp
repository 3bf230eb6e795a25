#include "methods/shadow_inputs.hpp"

#include <algorithm>
#include <array>

namespace shadowlab {

std::vector<ObjectBox> object_boxes(const Scene& scene) {
    std::vector<ObjectBox> boxes;
    boxes.reserve(scene.objects.size());
    for (const SceneObject& o : scene.objects) boxes.push_back({o.world_bounds(), o.casts, o.receives});
    return boxes;
}

namespace {

// The smallest signed distance of a box's points to a plane (its corner deepest inside).
double min_distance(const Aabb& b, const Plane& p) {
    const glm::dvec3 nearest{p.normal.x > 0 ? b.min.x : b.max.x, p.normal.y > 0 ? b.min.y : b.max.y,
                             p.normal.z > 0 ? b.min.z : b.max.z};
    return p.signed_distance(nearest);
}

// How far outside a frustum plane a box may lie and still cast a shadow in: its shadow (the box
// swept away from the light, at most `reach` for a directional light) crosses the plane only
// when the sweep moves inward. Conservative: a box within it counts as a caster.
std::array<double, 6> caster_allowance(const Frustum& frustum, const Light& light, double reach) {
    std::array<double, 6> allowance;
    for (size_t i = 0; i < 6; ++i) {
        const Plane& p = frustum.planes[i];
        allowance[i] = light.is_directional() ? std::max(0.0, -reach * glm::dot(p.normal, light.direction))
                                              : std::max(0.0, p.signed_distance(light.position));
    }
    return allowance;
}

std::vector<glm::dvec3> corners_of(const std::vector<Aabb>& boxes) {
    std::vector<glm::dvec3> points;
    points.reserve(boxes.size() * 8);
    for (const Aabb& b : boxes)
        for (const glm::dvec3& c : b.corners()) points.push_back(c);
    return points;
}

// A flat scene (a lone ground plane) still needs a body with volume.
Aabb padded(Aabb bounds) {
    const double pad = 1e-3 * std::max(bounds.diagonal(), 1e-6);
    for (int axis = 0; axis < 3; ++axis)
        if (bounds.max[axis] - bounds.min[axis] < pad) {
            bounds.min[axis] -= pad / 2;
            bounds.max[axis] += pad / 2;
        }
    return bounds;
}

}  // namespace

std::vector<glm::dvec3> ShadowInputs::receiver_points() const { return corners_of(receivers); }
std::vector<glm::dvec3> ShadowInputs::caster_points() const { return corners_of(casters); }

ShadowInputs gather_inputs(const Camera& camera, const Light& light, const std::vector<ObjectBox>& objects) {
    ShadowInputs in{camera, light, camera.frustum(), {}, {}, {}, {}};
    for (const ObjectBox& o : objects) in.scene_bounds.extend(o.box);
    in.scene_bounds = padded(in.scene_bounds);
    const double reach = in.scene_bounds.diagonal();
    in.receivers.reserve(objects.size());
    in.casters.reserve(objects.size());
    const std::array<double, 6> allowance = caster_allowance(in.frustum, light, reach);
    for (const ObjectBox& o : objects) {
        bool receiver = o.receives, caster = o.casts;  // until a plane separates it from the view
        for (size_t i = 0; i < 6 && (receiver || caster); ++i) {
            const double d = min_distance(o.box, in.frustum.planes[i]);
            receiver &= d <= 0.0;
            caster &= d <= allowance[i];
        }
        if (receiver) in.receivers.push_back(o.box);
        if (caster) in.casters.push_back(o.box);
    }
    return in;
}

ShadowInputs gather_inputs(const Scene& scene) { return gather_inputs(scene.camera, scene.light, object_boxes(scene)); }

}  // namespace shadowlab
