#include "model/camera_in_shadow.hpp"

#include <algorithm>
#include <cmath>

namespace shadowlab {
namespace {

// The ray parameter where q + t d leaves the box (q inside it).
double exit_distance(const Aabb& box, const glm::dvec3& q, const glm::dvec3& d) {
    double t = INFINITY;
    for (int a = 0; a < 3; ++a)
        if (d[a] != 0.0) t = std::min(t, ((d[a] > 0.0 ? box.max[a] : box.min[a]) - q[a]) / d[a]);
    return t;
}

bool clear_of_objects(const Scene& scene, const glm::dvec3& p) {
    return std::none_of(scene.objects.begin(), scene.objects.end(), [&](const SceneObject& o) {
        const Aabb box = o.world_bounds();
        return glm::all(glm::greaterThanEqual(p, box.min)) && glm::all(glm::lessThanEqual(p, box.max));
    });
}

// The spot in `caster`'s shadow, if it lies clear of the objects and above `ground`.
std::optional<glm::dvec3> spot_behind(const Scene& scene, const SceneObject& caster, double ground) {
    const Aabb box = caster.world_bounds();
    const glm::dvec3 q = 0.5 * (box.min + box.max) + glm::dvec3(0.0, 0.45 * (box.max.y - box.min.y), 0.0);
    const glm::dvec3 d =
        scene.light.is_directional() ? glm::normalize(scene.light.direction) : glm::normalize(q - scene.light.position);
    const glm::dvec3 p = q + (exit_distance(box, q, d) + 0.25 * box.diagonal()) * d;
    if (p.y < ground + 0.1 * box.diagonal() || !clear_of_objects(scene, p)) return std::nullopt;
    return p;
}

}  // namespace

std::optional<Camera> camera_in_shadow(const Scene& scene) {
    const double ground = scene.bounds().min.y;
    std::optional<glm::dvec3> best;
    for (const SceneObject& object : scene.objects) {
        if (!object.casts || object.shape == Shape::plane) continue;
        const std::optional<glm::dvec3> spot = spot_behind(scene, object, ground);
        if (spot && (!best || spot->y > best->y)) best = spot;
    }
    if (!best) return std::nullopt;
    Camera camera = scene.camera;
    const glm::dvec3 to_target = camera.target - *best;
    const bool target_in_view = glm::length(to_target) > 1e-6 &&
                                std::abs(glm::dot(glm::normalize(to_target), glm::normalize(camera.up))) < 0.95;
    if (!target_in_view) camera.target = *best + camera.view_direction();  // not straight up or down
    camera.position = *best;
    return camera;
}

}  // namespace shadowlab
