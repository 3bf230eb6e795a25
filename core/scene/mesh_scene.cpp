#include "scene/mesh_scene.hpp"

#include <algorithm>
#include <filesystem>

#include "scene/scene_loader.hpp"
#include "scene/triangle_mesh.hpp"

namespace shadowlab {

Scene scene_around_mesh(const std::string& mesh_file) {
    auto mesh = std::make_shared<const TriangleMesh>(load_triangle_mesh(mesh_file, mesh_file, "mesh"));
    const Aabb box = mesh->bounds();
    const double size = std::max(box.diagonal(), 1e-6);
    const glm::dvec3 centre = 0.5 * (box.min + box.max);

    Scene scene;
    scene.name = std::filesystem::path(mesh_file).stem().string();
    scene.source_file = mesh_file;
    SceneObject object;
    object.name = scene.name;
    object.shape = Shape::mesh;
    object.mesh_file = mesh_file;
    object.mesh = mesh;
    SceneObject ground;
    ground.name = "ground";
    ground.shape = Shape::plane;
    ground.position = {centre.x, box.min.y, centre.z};  // the mesh stands on it
    ground.size = {4.0 * size, 0.0, 4.0 * size};
    ground.casts = false;
    scene.objects = {ground, object};

    scene.camera.target = centre;
    scene.camera.position = centre + size * glm::dvec3(0.35, 0.6, 1.3);
    scene.camera.near = 0.01 * size;
    scene.camera.far = 10.0 * size;
    scene.light.direction = glm::normalize(glm::dvec3(-0.4, -1.0, -0.3));
    validate_scene(scene);  // a mesh far out or huge gets the loader's ranges and messages
    return scene;
}

}  // namespace shadowlab
