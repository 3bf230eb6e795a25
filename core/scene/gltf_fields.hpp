#pragma once
// Reading a glTF file's JSON field by field, each refusal naming the file and the field's JSON path
// (cameras[1].perspective.znear): shared by the scene's cameras and lights (gltf_scene) and its
// materials (gltf_materials).
#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>

#include "scene/scene_error.hpp"

namespace shadowlab {

// "path[index]", "path.key" (or "key" at the top).
std::string indexed(const std::string& path, std::size_t index);
std::string member_path(const std::string& path, const std::string& key);
// A value as messages quote it: significant digits; JSON text cut after 60 characters.
std::string shown(double value);
std::string shown(const nlohmann::json& value);

// Reads fields of the glTF JSON, refusing with the file and the field's path what the glTF 2.0
// schema or ShadowLab's camera and light cannot take.
class GltfFields {
public:
    explicit GltfFields(const std::string& file) : file_(file) {}

    [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
        throw SceneError(file_, path, problem);
    }

    // The member `key` of an object, or nullptr; the object itself must be one.
    const nlohmann::json* member(const nlohmann::json& object, const std::string& path, const char* key) const {
        if (!object.is_object()) fail(path, "expected an object, got " + std::string(object.type_name()));
        const auto found = object.find(key);
        return found == object.end() ? nullptr : &*found;
    }
    // The array `key` of an object; an empty one when absent.
    const nlohmann::json& array(const nlohmann::json& object, const std::string& path, const char* key) const {
        const nlohmann::json* value = member(object, path, key);
        if (value && !value->is_array()) fail(member_path(path, key), "expected an array");
        return value ? *value : no_items();
    }
    static const nlohmann::json& no_items() {
        static const nlohmann::json none = nlohmann::json::array();
        return none;
    }
    // The object at a chain of keys (extensions.KHR_lights_punctual), or nullptr.
    const nlohmann::json* nested(const nlohmann::json& object, const std::string& path,
                                 std::initializer_list<const char*> keys) const {
        const nlohmann::json* value = &object;
        std::string at = path;
        for (const char* key : keys) {
            value = member(*value, at, key);
            if (!value) return nullptr;
            at = member_path(at, key);
        }
        return value;
    }
    std::optional<double> number(const nlohmann::json& object, const std::string& path, const char* key) const {
        const nlohmann::json* value = member(object, path, key);
        if (!value) return std::nullopt;
        if (!value->is_number()) fail(member_path(path, key), "expected a number, got " + shown(*value));
        return value->get<double>();
    }
    double required_number(const nlohmann::json& object, const std::string& path, const char* key) const {
        const std::optional<double> value = number(object, path, key);
        if (!value) fail(member_path(path, key), "required, but missing");
        return *value;
    }
    // `count` numbers, or none when absent.
    std::vector<double> numbers(const nlohmann::json& object, const std::string& path, const char* key,
                                std::size_t count) const {
        const nlohmann::json* value = member(object, path, key);
        if (!value) return {};
        const bool ok =
            value->is_array() && value->size() == count &&
            std::all_of(value->begin(), value->end(), [](const nlohmann::json& item) { return item.is_number(); });
        if (!ok) fail(member_path(path, key), "expected an array of " + std::to_string(count) + " numbers");
        return value->get<std::vector<double>>();
    }
    std::string text(const nlohmann::json& object, const std::string& path, const char* key) const {
        const nlohmann::json* value = member(object, path, key);
        if (!value || !value->is_string()) fail(member_path(path, key), "expected a string");
        return value->get<std::string>();
    }
    // An index into an array of `count` items.
    std::size_t index(const nlohmann::json& value, const std::string& path, std::size_t count) const {
        if (value.is_number_unsigned() && value.get<std::uint64_t>() < count) return value.get<std::size_t>();
        if (count == 0) fail(path, "an index into an array the file leaves empty or out, got " + shown(value));
        fail(path, "expected an index below " + std::to_string(count) + ", got " + shown(value));
    }
    std::optional<std::size_t> index(const nlohmann::json& object, const std::string& path, const char* key,
                                     std::size_t count) const {
        const nlohmann::json* value = member(object, path, key);
        return value ? std::optional(index(*value, member_path(path, key), count)) : std::nullopt;
    }
    void expect(bool ok, const std::string& path, const std::string& expected, double got) const {
        if (!ok) fail(path, "expected " + expected + ", got " + shown(got));
    }

private:
    const std::string& file_;
};

}  // namespace shadowlab
