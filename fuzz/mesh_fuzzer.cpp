// libFuzzer target: the input as a model file a user opens (OBJ, PLY, STL, glTF or GLB, named by
// what its first bytes look like, as a user names a file), through the path `shadowlab` takes:
// Assimp in its child process, the nodes carried back, the scene built around them. A refusal is the
// right answer to bad input, a crash of Assimp in its child included; once a scene is accepted,
// every method runs on it (every_method).
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "every_method.hpp"
#include "scene/scene_error.hpp"
#include "scene/scene_loader.hpp"

namespace shadowlab {
namespace {

std::string extension_for(const std::string& bytes) {
    if (bytes.starts_with("glTF")) return ".glb";
    if (bytes.starts_with("{")) return ".gltf";
    if (bytes.starts_with("ply")) return ".ply";
    if (bytes.starts_with("solid") || (bytes.size() >= 84 && bytes.find('\0') < 84)) return ".stl";
    return ".obj";
}

// One file per fuzzing process, written again for every input.
std::filesystem::path input_file(const std::string& extension) {
    return std::filesystem::temp_directory_path() / ("shadowlab_mesh_fuzz_" + std::to_string(getpid()) + extension);
}

}  // namespace
}  // namespace shadowlab

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace shadowlab;
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    const std::filesystem::path file = input_file(extension_for(bytes));
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
    Scene scene;
    try {
        scene = load_scene(file.string());
    } catch (const SceneError&) {
        return 0;
    }
    try {
        fuzzing::run_every_method(std::move(scene));
    } catch (const std::exception& error) {
        fuzzing::bug("an accepted model", std::string("threw: ") + error.what());
    }
    return 0;
}
