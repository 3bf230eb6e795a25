#pragma once
// A glTF scene as its file has it (.gltf, or the binary .glb): each node holding meshes one object
// (casting and receiving), the camera and the KHR_lights_punctual light chosen (the first of each
// by default), placed by the nodes that hold them. What the file lacks is defaulted and said:
// without a camera the file is a model (mesh_scene's camera and ground plane), without a light
// mesh_scene's sun. See README.md, "Scene format", glTF scenes.
#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_choice.hpp"

namespace shadowlab {

struct GltfScene {
    Scene scene;
    std::vector<std::string> defaulted;  // what the file lacks and ShadowLab assumed, one line each
};

// One camera or light a glTF file offers: its name (its own, else that of the first node holding
// it; may be empty) and its type ("perspective", "orthographic"; "directional", "point", "spot").
struct GltfItem {
    std::string name;
    std::string type;
};

// What a glTF file offers to choose from, in the file's order: its cameras and its KHR_lights_punctual
// lights. A file without a camera or a light gets the default one: it still offers one choice.
struct GltfContents {
    std::vector<GltfItem> cameras;
    std::vector<GltfItem> lights;

    std::size_t camera_choices() const { return std::max<std::size_t>(cameras.size(), 1); }
    std::size_t light_choices() const { return std::max<std::size_t>(lights.size(), 1); }
};

// By the extension, in any case: .gltf, .glb.
bool is_gltf_file(const std::string& file);

// Throws SceneError naming the file and the glTF JSON path on a malformed file or a camera or light
// without a type.
GltfContents gltf_contents(const std::string& file);

// Throws SceneError naming the file and the glTF JSON path (cameras[1].perspective.znear) on a
// malformed file (JSON, a .glb header, a buffer Assimp cannot read), on values a camera or light
// cannot have, and on a choice beyond the file's cameras or lights; then validate_scene's rules.
GltfScene read_gltf_scene(const std::string& file, const SceneChoice& choice = {});
// The same but for validate_scene, for a caller that changes the scene before checking it (a scene
// JSON referencing the file sets its objects' roles: a light inside a mesh that does not cast is fine).
GltfScene read_gltf_scene_unvalidated(const std::string& file, const SceneChoice& choice = {});

// Refuses the `index`-th camera or light (`what`) of a file that holds `count`, by `file` and
// `json_path`: "camera 2 asked for, but <holder> holds 2 cameras (0 … 1)".
void check_choice(const std::string& file, const std::string& json_path, const std::string& what, std::size_t index,
                  std::size_t count, const std::string& holder);

}  // namespace shadowlab
