#pragma once
// Where in a scene file's JSON a problem lies, for messages that name it: a syntax error by its
// line and column, a field by its JSON path (camera.position, objects[3].size).
#include <string>
#include <nlohmann/json.hpp>

namespace shadowlab {

// The path of member `key` of the value at `path`: "key" at the top, else "path.key".
std::string join_path(const std::string& path, const std::string& key);

// The document `text` holds. Throws SceneError naming `file` and, for a syntax error, its line and
// column; for a number too large for a double (1e999, which nlohmann refuses), its JSON path.
nlohmann::json parse_scene_json(const std::string& text, const std::string& file);

}  // namespace shadowlab
