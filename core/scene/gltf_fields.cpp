#include "scene/gltf_fields.hpp"

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

}  // namespace shadowlab
