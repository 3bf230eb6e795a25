#include "scene/gltf_fields.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/value_text.hpp"

namespace shadowlab {

std::string indexed(const std::string& path, std::size_t index) { return path + "[" + std::to_string(index) + "]"; }
std::string member_path(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
}
std::string shown(double value) { return significant(value, kValueDigits); }
std::string shown(const nlohmann::json& value) {
    constexpr std::size_t kMaxShownChars = 60;  // a long value is cut in messages
    const std::string text = value.dump();
    return text.size() <= kMaxShownChars ? text : text.substr(0, kMaxShownChars - 3) + "...";
}

std::string file_bytes(const std::string& file) {
    std::error_code error;
    std::ifstream in(file, std::ios::binary);
    if (!std::filesystem::is_regular_file(file, error) || !in) throw SceneError(file, "", "cannot open file");
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

}  // namespace shadowlab
