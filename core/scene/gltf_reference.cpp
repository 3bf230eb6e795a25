// A scene JSON referencing a glTF scene: reading it is scene_loader's (the same strict keys as every
// scene JSON); here the referenced scene is made from it, and the JSON written from a scene.
#include "scene/gltf_reference.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "scene/scene_error.hpp"
#include "scene/scene_validation.hpp"

namespace shadowlab {
namespace {

// Names in a message: the first few, then how many more.
std::string names_of(const std::vector<SceneObject>& objects) {
    constexpr std::size_t kMaxNamesShown = 8;
    std::string out;
    for (std::size_t i = 0; i < std::min(objects.size(), kMaxNamesShown); ++i)
        out += (i == 0 ? "" : ", ") + objects[i].name;
    if (objects.size() > kMaxNamesShown) out += " and " + std::to_string(objects.size() - kMaxNamesShown) + " more";
    return out;
}

// Gives every object called `name` its roles; false when none is.
bool give_roles(std::vector<SceneObject>& objects, const std::string& name, const ObjectRoles& roles) {
    bool named = false;
    for (SceneObject& object : objects) {
        if (object.name != name) continue;
        object.casts = roles.casts;
        object.receives = roles.receives;
        named = true;
    }
    return named;
}

// The glTF file as the JSON should name it: relative to the JSON's directory, so that the two move
// together, unless they lie on different roots (another drive).
std::string path_from_json(const std::string& json_file, const std::string& gltf_file) {
    namespace fs = std::filesystem;
    const fs::path gltf = fs::absolute(gltf_file).lexically_normal();
    const fs::path relative = gltf.lexically_relative(fs::absolute(json_file).parent_path().lexically_normal());
    return (relative.empty() ? gltf : relative).generic_string();
}

}  // namespace

GltfScene referenced_scene(const GltfReference& reference, const std::string& json_file) {
    const GltfContents contents = gltf_contents(reference.gltf_file);
    check_choice(json_file, "camera", "camera", reference.choice.camera, contents.camera_choices(),
                 reference.gltf_file);
    check_choice(json_file, "light", "light", reference.choice.light, contents.light_choices(), reference.gltf_file);
    GltfScene gltf = read_gltf_scene_unvalidated(reference.gltf_file, reference.choice);
    Scene& scene = gltf.scene;
    for (const auto& [name, roles] : reference.roles)
        if (!give_roles(scene.objects, name, roles))
            throw SceneError(
                json_file, "objects." + name,
                "no object of " + reference.gltf_file + " has this name; its objects: " + names_of(scene.objects));
    validate_scene(scene);  // in the glTF file's name: its objects, camera and light are the file's
    scene.source_file = json_file;
    if (!reference.name.empty()) scene.name = reference.name;
    return gltf;
}

std::map<std::string, ObjectRoles> roles_by_name(const Scene& scene, const std::string& file) {
    std::map<std::string, ObjectRoles> by_name;
    for (const SceneObject& object : scene.objects) {
        const ObjectRoles roles{.casts = object.casts, .receives = object.receives};
        const auto [named, first] = by_name.try_emplace(object.name, roles);
        if (!first && named->second != roles)
            throw SceneError(file, "objects." + object.name,
                             "objects sharing this name differ in their roles, which a name cannot tell apart");
    }
    std::erase_if(by_name, [](const auto& named) { return named.second == ObjectRoles{}; });
    return by_name;
}

void save_scene_referencing_gltf(const std::string& json_file, const std::string& gltf_file, const SceneChoice& choice,
                                 const Scene& scene) {
    nlohmann::ordered_json objects = nlohmann::ordered_json::object();
    for (const auto& [name, roles] : roles_by_name(scene, json_file))
        objects[name] = {{"casts", roles.casts}, {"receives", roles.receives}};
    const nlohmann::ordered_json root = {{"name", scene.name},
                                         {"gltf", path_from_json(json_file, gltf_file)},
                                         {"camera", choice.camera},
                                         {"light", choice.light},
                                         {"objects", objects}};
    std::ofstream out(json_file, std::ios::binary);
    if (!(out << root.dump(2) << "\n")) throw SceneError(json_file, "", "cannot write file");
}

}  // namespace shadowlab
