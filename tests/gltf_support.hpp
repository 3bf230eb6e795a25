#pragma once
// A small glTF scene written by the tests: one quad mesh placed twice (a ground and a roof), two
// cameras, a sun and a bulb (KHR_lights_punctual), its buffer embedded as base64.
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <glm/glm.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace shadowlab::testing {

inline std::string base64(const std::string& bytes) {
    static const char* const digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);  // bytes in this group
        std::uint32_t group = 0;
        for (std::size_t k = 0; k < 3; ++k)
            group = (group << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
        for (std::size_t k = 0; k < 4; ++k) out += k <= n ? digits[(group >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

// The quad x, z in [-1, 1] at y = 0, facing +y: four float positions, then six uint16 indices.
inline std::string quad_buffer() {
    std::string bytes;
    const auto append = [&](const auto& value) { bytes.append(reinterpret_cast<const char*>(&value), sizeof value); };
    for (float coordinate : {-1.f, 0.f, -1.f, 1.f, 0.f, -1.f, 1.f, 0.f, 1.f, -1.f, 0.f, 1.f}) append(coordinate);
    for (std::uint16_t index : {0, 2, 1, 0, 3, 2}) append(index);
    return bytes;
}

// glTF's rotation [x, y, z, w]: `degrees` about a unit axis.
inline nlohmann::json turn(const glm::dvec3& axis, double degrees) {
    const double half = glm::radians(degrees) / 2.0;
    return {axis.x * std::sin(half), axis.y * std::sin(half), axis.z * std::sin(half), std::cos(half)};
}

// The scene's placements, which the tests expect back.
constexpr double kMainCameraTilt = -20.0;  // degrees about x: looks down
constexpr double kSunTilt = -60.0;         // degrees about x: the sun's node, shining down its −z

// The ground is the quad scaled by 10, the roof the quad raised by 2. The main camera (perspective,
// every field) stands at (0, 3, 8) tilted down; the side camera (no aspect, no far) stands in a rig at
// x = 5, raised by 1 and turned 90° about y to look along −x. The sun is tilted 60° down; the bulb
// (a point light reaching 20) hangs at (1, 4, 1).
inline nlohmann::json two_camera_scene() {
    nlohmann::json gltf = nlohmann::json::parse(R"({
      "asset": {"version": "2.0"},
      "extensionsUsed": ["KHR_lights_punctual"],
      "buffers": [{"byteLength": 60}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                      {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                     "min": [-1, 0, -1], "max": [1, 0, 1]},
                    {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}],
      "meshes": [{"name": "quad", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
      "cameras": [{"type": "perspective",
                   "perspective": {"yfov": 0.8, "aspectRatio": 1.5, "znear": 0.05, "zfar": 200}},
                  {"type": "perspective", "perspective": {"yfov": 0.5, "znear": 0.1}}],
      "extensions": {"KHR_lights_punctual": {"lights": [{"type": "directional"},
                                                        {"type": "point", "range": 20}]}},
      "nodes": [{"name": "ground", "mesh": 0, "scale": [10, 1, 10]},
                {"name": "roof", "mesh": 0, "translation": [0, 2, 0]},
                {"name": "main camera", "camera": 0, "translation": [0, 3, 8]},
                {"name": "rig", "translation": [5, 0, 0], "children": [4]},
                {"name": "side camera", "camera": 1, "translation": [0, 1, 0]},
                {"name": "sun", "extensions": {"KHR_lights_punctual": {"light": 0}}},
                {"name": "bulb", "translation": [1, 4, 1], "extensions": {"KHR_lights_punctual": {"light": 1}}}],
      "scenes": [{"nodes": [0, 1, 2, 3, 5, 6]}],
      "scene": 0})");
    gltf["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(quad_buffer());
    gltf["nodes"][2]["rotation"] = turn({1.0, 0.0, 0.0}, kMainCameraTilt);
    gltf["nodes"][4]["rotation"] = turn({0.0, 1.0, 0.0}, 90.0);
    gltf["nodes"][5]["rotation"] = turn({1.0, 0.0, 0.0}, kSunTilt);
    return gltf;
}

// Writes `text` to a fresh file of that name in this test process's own temporary directory (ctest
// runs tests in parallel, each in a process of its own: a shared name would be written under another).
inline std::string write_test_file(const std::string& name, const std::string& text) {
    const std::filesystem::path dir =
        std::filesystem::path(::testing::TempDir()) / ("shadowlab_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::filesystem::path path = dir / name;
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
}

}  // namespace shadowlab::testing
