#include "scene/mesh_scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <assimp/Importer.hpp>

#include "scene/scene_validation.hpp"
#include "scene/triangle_mesh.hpp"

namespace shadowlab {
namespace {

constexpr double kCameraAzimuthDeg = 70.0;         // 20° right of the front (+z, glTF's forward)
constexpr double kCameraElevationDeg = 30.0;       // looking down this much
constexpr double kFramingMargin = 1.15;            // the sphere spans 1 / 1.15 of the narrower half-angle
constexpr double kSunAzimuthFromCameraDeg = 60.0;  // behind the camera, to its left
constexpr double kSunElevationDeg = 50.0;
constexpr double kGroundMargin = 0.25;  // radii of ground beyond the footprint and the shadow
constexpr double kGroundReach = 3.0;    // radii from the centre, at most, along x and along z
constexpr double kNearOfGap = 0.5;      // the near plane halfway from the eye to the sphere

// The bounds' sphere: their centre, and half their diagonal (never 0: a point still gets a view).
struct BoundingSphere {
    glm::dvec3 centre;
    double radius;
};
BoundingSphere sphere_of(const Aabb& box) {
    return {.centre = box.center(), .radius = std::max(0.5 * box.diagonal(), 1e-6)};
}

// The unit vector from a target toward a sky position at these angles (light.hpp's convention).
glm::dvec3 toward_sky(double azimuth_deg, double elevation_deg) {
    return -light_direction_from_angles(azimuth_deg, elevation_deg);
}

// Where the light throws `point` on the plane y = ground_y. A ray that never comes down to the
// plane (a lamp at the point's height or below) is sent along its sideways heading to `beyond`.
glm::dvec3 shadow_on_ground(const glm::dvec3& point, const Light& light, double ground_y, double beyond) {
    const glm::dvec3 ray = light.is_directional() ? light.direction : point - light.position;
    const glm::dvec2 sideways(ray.x, ray.z);
    const double sideways_length = glm::length(sideways);
    if (sideways_length == 0.0) return {point.x, ground_y, point.z};
    const double run = ray.y < 0.0 ? (point.y - ground_y) * sideways_length / -ray.y : beyond;
    const glm::dvec2 step = std::min(run, beyond) * sideways / sideways_length;
    return {point.x + step.x, ground_y, point.z + step.y};
}

}  // namespace

Scene scene_around_mesh(const std::string& mesh_file) {
    // Absolute: load_triangle_mesh reads a relative path as relative to the scene file's directory.
    const std::string path = std::filesystem::absolute(mesh_file).string();
    auto mesh = std::make_shared<const TriangleMesh>(load_triangle_mesh(path, mesh_file, "mesh"));
    Scene scene;
    scene.name = std::filesystem::path(mesh_file).stem().string();
    scene.source_file = mesh_file;
    SceneObject object;
    object.name = scene.name;
    object.shape = Shape::mesh;
    object.mesh_file = mesh_file;
    object.mesh = mesh;
    object.material_alpha = opacity_alpha_tests(*mesh, path, mesh_file, "mesh");
    object.material_colour = material_colours(*mesh, path, mesh_file, scene.notes);
    scene.camera = camera_framing(mesh->bounds());
    scene.light = sun_beside(scene.camera);
    scene.objects = {ground_under(mesh->bounds(), scene.light), object};
    validate_scene(scene);  // a mesh far out or huge gets the loader's ranges and messages
    return scene;
}

bool is_mesh_file(const std::string& file) {
    const std::string extension = std::filesystem::path(file).extension().string();
    return !extension.empty() && extension != ".json" && Assimp::Importer().IsExtensionSupported(extension);
}

Camera camera_framing(const Aabb& meshes) {
    const BoundingSphere sphere = sphere_of(meshes);
    Camera camera;
    // The narrower of the view's half-angles; the sphere, seen from d, spans asin(r / d) of it.
    const double half_y = 0.5 * glm::radians(camera.fov_y_deg);
    const double half_x = std::atan(camera.aspect * std::tan(half_y));
    const double distance = kFramingMargin * sphere.radius / std::sin(std::min(half_x, half_y));
    camera.target = sphere.centre;
    camera.position = sphere.centre + distance * toward_sky(kCameraAzimuthDeg, kCameraElevationDeg);
    camera.near = kNearOfGap * (distance - sphere.radius);
    // The farthest ground corner is at most (kGroundReach, 1, kGroundReach) radii from the centre.
    camera.far = distance + glm::length(glm::dvec3(kGroundReach, 1.0, kGroundReach)) * sphere.radius;
    return camera;
}

Light sun_beside(const Camera& camera) {
    const LightAngles seen_from = light_angles(camera.view_direction());  // the camera's own azimuth
    Light sun;
    sun.direction = light_direction_from_angles(seen_from.azimuth_deg + kSunAzimuthFromCameraDeg, kSunElevationDeg);
    return sun;
}

SceneObject ground_under(const Aabb& meshes, const Light& light) {
    const BoundingSphere sphere = sphere_of(meshes);
    const double ground_y = meshes.min.y;  // the meshes stand on it
    const double reach = kGroundReach * sphere.radius;
    Aabb held;  // the footprint and the shadow of every corner of the bounds
    for (const glm::dvec3& corner : meshes.corners()) {
        held.extend(glm::dvec3(corner.x, ground_y, corner.z));
        held.extend(shadow_on_ground(corner, light, ground_y, 2.0 * reach));
    }
    const glm::dvec3 margin(kGroundMargin * sphere.radius, 0.0, kGroundMargin * sphere.radius);
    const glm::dvec3 farthest(reach, 0.0, reach);
    const glm::dvec3 low = glm::max(held.min - margin, sphere.centre - farthest);
    const glm::dvec3 high = glm::min(held.max + margin, sphere.centre + farthest);
    SceneObject ground;
    ground.name = "ground";
    ground.shape = Shape::plane;
    ground.position = {0.5 * (low.x + high.x), ground_y, 0.5 * (low.z + high.z)};
    ground.size = {high.x - low.x, 0.0, high.z - low.z};
    ground.casts = false;
    return ground;
}

}  // namespace shadowlab
