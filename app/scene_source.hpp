#pragma once
// The scene a command works on: which of its file's cameras and lights, and the engine camera that
// may replace the file's (`--camera-matrices`, core/exchange/camera_import.hpp).
#include <map>
#include <string>

#include "scene/scene_loader.hpp"

namespace shadowlab {

struct SceneSource {
    SceneChoice choice;           // which of the file's cameras and lights (a glTF file may hold several)
    std::string camera_matrices;  // an engine's view and projection; empty: the file's own camera
    std::map<std::string, std::string> camera_conventions;  // key -> value, as camera_convention_settings() names them
};

// The scene of `file` as `source` chooses it, its camera replaced by the engine's when one is named.
// Throws SceneError for the scene, std::invalid_argument naming the matrices file and field.
Scene load_scene_source(const std::string& file, const SceneSource& source);

}  // namespace shadowlab
