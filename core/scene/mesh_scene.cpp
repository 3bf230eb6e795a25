#include "scene/mesh_scene.hpp"

#include <algorithm>
#include <filesystem>
#include <assimp/Importer.hpp>

#include "scene/scene_loader.hpp"
#include "scene/triangle_mesh.hpp"

namespace shadowlab {
namespace {

double size_of(const Aabb& box) { return std::max(box.diagonal(), 1e-6); }
glm::dvec3 centre_of(const Aabb& box) { return 0.5 * (box.min + box.max); }

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
    scene.objects = {ground_under(mesh->bounds()), object};
    scene.camera = camera_framing(mesh->bounds());
    scene.light = sun_from_above();
    validate_scene(scene);  // a mesh far out or huge gets the loader's ranges and messages
    return scene;
}

bool is_mesh_file(const std::string& file) {
    const std::string extension = std::filesystem::path(file).extension().string();
    return !extension.empty() && extension != ".json" && Assimp::Importer().IsExtensionSupported(extension);
}

SceneObject ground_under(const Aabb& meshes) {
    const double size = size_of(meshes);
    const glm::dvec3 centre = centre_of(meshes);
    SceneObject ground;
    ground.name = "ground";
    ground.shape = Shape::plane;
    ground.position = {centre.x, meshes.min.y, centre.z};  // the meshes stand on it
    ground.size = {4.0 * size, 0.0, 4.0 * size};
    ground.casts = false;
    return ground;
}

Camera camera_framing(const Aabb& meshes) {
    const double size = size_of(meshes);
    Camera camera;
    camera.target = centre_of(meshes);
    camera.position = camera.target + size * glm::dvec3(0.35, 0.6, 1.3);
    camera.near = 0.01 * size;
    camera.far = 10.0 * size;
    return camera;
}

Light sun_from_above() {
    Light sun;
    sun.direction = glm::normalize(glm::dvec3(-0.4, -1.0, -0.3));
    return sun;
}

}  // namespace shadowlab
