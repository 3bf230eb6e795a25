#include "scene/scene.hpp"

#include <map>

namespace shadowlab {

Aabb Scene::bounds() const {
    Aabb box;
    for (const SceneObject& object : objects) box.extend(object.world_bounds());
    return box;
}

std::vector<std::string> loading_notes(const Scene& scene) {
    std::vector<std::string> files;  // in the objects' order
    std::map<std::string, std::size_t> broken;
    for (const SceneObject& object : scene.objects) {
        if (!object.mesh || object.mesh->broken_faces_dropped == 0) continue;
        if (!broken.contains(object.mesh_file)) files.push_back(object.mesh_file);
        broken[object.mesh_file] += object.mesh->broken_faces_dropped;
    }
    std::vector<std::string> notes;
    for (const std::string& file : files) notes.push_back(broken_faces_note(file, broken[file]));
    for (const Note& note : scene.notes) notes.push_back(describe(note));
    return notes;
}

}  // namespace shadowlab
