#pragma once
// Reading and validating scene files (JSON; glTF and lone meshes by their own readers). See README.md,
// "Scene format".
#include <cstddef>
#include <string>

#include "scene/scene.hpp"

namespace shadowlab {

// Which of a file's cameras and lights the scene takes, 0-based. A glTF file may hold several; a
// scene JSON and a lone mesh hold one of each (the default).
struct SceneChoice {
    std::size_t camera = 0;
    std::size_t light = 0;
};

// By the file's extension: a glTF scene (.gltf, .glb: gltf_scene, what it lacks named on stderr), a
// lone mesh (OBJ, PLY, STL, ...: scene_around_mesh) or a scene JSON (anything else). Throws SceneError
// (file, JSON path, what was expected) on any invalid input, a choice beyond the file's cameras or
// lights included.
Scene load_scene(const std::string& path, const SceneChoice& choice = {});
// Same, from JSON text; `file` is used in messages and to resolve relative mesh paths.
Scene parse_scene(const std::string& json_text, const std::string& file);
// Checks an in-memory scene (e.g. built in code or edited in the GUI) by the same rules.
void validate_scene(const Scene& scene);

}  // namespace shadowlab
