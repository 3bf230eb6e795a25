#pragma once
// Reading and validating scene files (JSON). See README.md, "Scene format".
#include <string>

#include "scene/scene.hpp"

namespace shadowlab {

// Throws SceneError (file, JSON path, what was expected) on any invalid input.
Scene load_scene(const std::string& path);
// Same, from JSON text; `file` is used in messages and to resolve relative mesh paths.
Scene parse_scene(const std::string& json_text, const std::string& file);
// Checks an in-memory scene (e.g. built in code or edited in the GUI) by the same rules.
void validate_scene(const Scene& scene);

}  // namespace shadowlab
