#pragma once
// A scene JSON that references a glTF scene rather than listing objects of its own: the file, which
// of its cameras and lights, and the roles of its objects by name (the window marks meshes that
// neither cast nor receive, and saves them so). See README.md, "Scene format".
//
//   {"name": "town", "gltf": "town.glb", "camera": 1, "light": 0,
//    "objects": {"awning": {"casts": false}, "lamp shade": {"casts": false, "receives": false}}}
#include <map>
#include <string>

#include "scene/gltf_scene.hpp"
#include "scene/scene.hpp"
#include "scene/scene_choice.hpp"

namespace shadowlab {

// What an object of a glTF scene does; the file has every object cast and receive.
struct ObjectRoles {
    bool casts = true;
    bool receives = true;

    bool operator==(const ObjectRoles&) const = default;
};

struct GltfReference {
    std::string gltf_file;  // as given when absolute, else joined to the referencing JSON's directory
    SceneChoice choice;
    std::map<std::string, ObjectRoles> roles;  // by object name; an object not named casts and receives
    std::string name;                          // the scene's; empty: the glTF file's stem
};

// The glTF scene with the chosen camera and light and each named object given its roles, then
// validated (so a light inside a mesh that does not cast is fine). Throws SceneError naming
// `json_file` and the JSON path for a choice beyond the file's cameras or lights ("camera") or a
// name no object has ("objects.roof"), and the glTF file's own problems as read_gltf_scene does.
GltfScene referenced_scene(const GltfReference& reference, const std::string& json_file);

// The roles of the scene's objects that do not both cast and receive, by name. Throws SceneError
// naming `file` when objects sharing a name differ in their roles (a name could not tell them apart).
std::map<std::string, ObjectRoles> roles_by_name(const Scene& scene, const std::string& file);

// Writes the scene JSON referencing `gltf_file` (by a path relative to the JSON's directory when
// there is one) with `choice`, the scene's name and its roles_by_name. Throws SceneError naming
// `json_file` as roles_by_name does, or when the file cannot be written.
void save_scene_referencing_gltf(const std::string& json_file, const std::string& gltf_file, const SceneChoice& choice,
                                 const Scene& scene);

}  // namespace shadowlab
