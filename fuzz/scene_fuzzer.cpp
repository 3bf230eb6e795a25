// libFuzzer target: the input as a scene file and, when the loader accepts it, every method of the
// registry on it (every_method). A refusal (SceneError, naming file and field) is the right answer
// to bad input.
#include <cstdint>
#include <string>
#include <nlohmann/json.hpp>

#include "every_method.hpp"
#include "scene/scene_error.hpp"
#include "scene/scene_loader.hpp"

namespace shadowlab {
namespace {

// The fuzzer reads no file but its input, so a scene with a mesh object is skipped before the
// loader would open the mesh. The JSON is parsed rather than searched: "m\u0065sh" names a mesh too.
bool names_a_mesh(const std::string& text) {
    const nlohmann::json scene = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    const auto objects = scene.is_object() ? scene.find("objects") : scene.end();
    if (objects == scene.end() || !objects->is_array()) return false;
    for (const nlohmann::json& object : *objects)
        if (object.is_object() && object.contains("type") && object["type"] == "mesh") return true;
    return false;
}

}  // namespace
}  // namespace shadowlab

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace shadowlab;
    const std::string text(reinterpret_cast<const char*>(data), size);
    if (names_a_mesh(text)) return 0;
    Scene scene;
    try {
        scene = parse_scene(text, "fuzz.json");
    } catch (const SceneError&) {
        return 0;
    }
    try {
        fuzzing::run_every_method(std::move(scene));
    } catch (const std::exception& error) {
        fuzzing::bug("an accepted scene", std::string("threw: ") + error.what());
    }
    return 0;
}
