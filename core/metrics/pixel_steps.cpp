#include "metrics/pixel_steps.hpp"

namespace shadowlab {
namespace {

// Faces turned from the light (or edge-on to it) are dark by shading whatever a map says: only
// pixels of receivers that face the light are judged.
constexpr float kMinFacing = 1e-3f;

// The neighbour one pixel along (dx, dy), or the one on the other side when that is off the
// object; its offset sign tells which was used. -1 when neither lies on the same object.
long neighbour(const ReferenceImage& ref, int x, int y, int dx, int dy, double& sign) {
    const size_t i = size_t(y) * ref.width + x;
    for (int s : {1, -1}) {
        const int nx = x + s * dx, ny = y + s * dy;
        if (nx < 0 || ny < 0 || nx >= ref.width || ny >= ref.height) continue;
        const size_t n = size_t(ny) * ref.width + nx;
        if (ref.visible[n] && ref.object[n] == ref.object[i]) {
            sign = s;
            return long(n);
        }
    }
    return -1;
}

// Where the camera's ray through `seen` (from the eye, or parallel to the view for an orthographic
// camera) meets the plane through p with normal n.
glm::dvec3 along_ray_onto_plane(const Camera& camera, const glm::dvec3& seen, const glm::dvec3& p,
                                const glm::dvec3& n) {
    const glm::dvec3 eye = camera.eye_of(seen), ray = seen - eye;
    return eye + ray * (glm::dot(n, p - eye) / glm::dot(n, ray));
}

}  // namespace

bool receives(const Scene& scene, const ReferenceImage& ref, size_t i) {
    return ref.visible[i] && scene.objects[ref.object[i]].receives && ref.facing[i] > kMinFacing;
}

glm::dvec3 along_light(const Light& light, const glm::dvec3& p) {
    return light.is_directional() ? light.direction : glm::normalize(p - light.position);
}

std::optional<PixelSteps> pixel_steps(const Scene& scene, const ReferenceImage& ref, int x, int y) {
    PixelSteps s;
    const size_t i = size_t(y) * ref.width + x;
    if (!receives(scene, ref, i)) return std::nullopt;
    const long right = neighbour(ref, x, y, 1, 0, s.right_sign), down = neighbour(ref, x, y, 0, 1, s.down_sign);
    if (right < 0 || down < 0) return std::nullopt;
    s.point = ref.position[i];
    s.right = ref.position[right];
    s.down = ref.position[down];
    const Camera& camera = scene.camera;
    const glm::dvec3 halfway =
        glm::normalize(glm::normalize(camera.eye_of(s.point) - s.point) - along_light(scene.light, s.point));
    s.right_on_halfway = along_ray_onto_plane(camera, s.right, s.point, halfway);
    s.down_on_halfway = along_ray_onto_plane(camera, s.down, s.point, halfway);
    return s;
}

}  // namespace shadowlab
