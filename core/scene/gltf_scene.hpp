#pragma once
// A glTF scene as its file has it (.gltf, or the binary .glb): each node holding meshes one object
// (casting and receiving), the camera and the KHR_lights_punctual light chosen (the first of each
// by default), placed by the nodes that hold them. What the file lacks is defaulted and said:
// without a camera the file is a model (mesh_scene's camera and ground plane), without a light
// mesh_scene's sun. See README.md, "Scene format", glTF scenes.
#include <cstddef>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_loader.hpp"

namespace shadowlab {

struct GltfScene {
    Scene scene;
    std::vector<std::string> defaulted;  // what the file lacks and ShadowLab assumed, one line each
};

// By the extension, in any case: .gltf, .glb.
bool is_gltf_file(const std::string& file);

// Throws SceneError naming the file and the glTF JSON path (cameras[1].perspective.znear) on a
// malformed file (JSON, a .glb header, a buffer Assimp cannot read), on values a camera or light
// cannot have, and on a choice beyond the file's cameras or lights; then validate_scene's rules.
GltfScene read_gltf_scene(const std::string& file, const SceneChoice& choice = {});

// Refuses, naming the file, the `index`-th camera or light (`what`) of a file that holds `count`.
void check_choice(const std::string& file, const std::string& what, std::size_t index, std::size_t count);

}  // namespace shadowlab
