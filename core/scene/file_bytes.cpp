#include "scene/file_bytes.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/scene_error.hpp"

namespace shadowlab {

std::string file_bytes(const std::string& file) {
    std::error_code error;
    std::ifstream in(file, std::ios::binary);
    if (!std::filesystem::is_regular_file(file, error) || !in) throw SceneError(file, "", "cannot open file");
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

}  // namespace shadowlab
