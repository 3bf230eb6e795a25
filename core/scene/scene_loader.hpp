#pragma once
// Reading and validating scene files (JSON; glTF and lone meshes by their own readers). See README.md,
// "Scene format".
#include <optional>
#include <string>

#include "scene/gltf_reference.hpp"
#include "scene/scene.hpp"
#include "scene/scene_choice.hpp"
#include "scene/scene_validation.hpp"  // validate_scene: the same rules for an in-memory scene

namespace shadowlab {

// By the file's extension: a glTF scene (.gltf, .glb: gltf_scene, what it lacks named on stderr), a
// lone mesh (OBJ, PLY, STL, ...: scene_around_mesh) or a scene JSON (anything else; one with a "gltf"
// key references a glTF scene: gltf_reference). Throws SceneError (file, JSON path, what was expected)
// on any invalid input, a choice beyond the file's cameras or lights included.
Scene load_scene(const std::string& path, const SceneChoice& choice = {});
// Same, from JSON text; `file` is used in messages and to resolve relative mesh and glTF paths.
Scene parse_scene(const std::string& json_text, const std::string& file);
// The glTF scene a file stands for: a .gltf or .glb file itself (with `choice`, no roles), or the one a
// scene JSON references (its choice and roles); nullopt for a scene JSON of its own or a lone mesh.
// Throws as load_scene does on a malformed file.
std::optional<GltfReference> gltf_reference_of(const std::string& path, const SceneChoice& choice = {});

}  // namespace shadowlab
