#pragma once
// Scenes and checks shared by the method tests.
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "methods/method.hpp"
#include "scene/scene.hpp"

namespace shadowlab::testing {

inline std::string source_path(const std::string& relative) {
    return (std::filesystem::path(SHADOWLAB_SOURCE_DIR) / relative).string();
}

inline std::vector<std::string> shipped_scenes() {
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(source_path("data/scenes")))
        if (entry.path().extension() == ".json") files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

// A ground plane and `count` boxes scattered over [-size/2, size/2]^2, heights up to size/5.
inline Scene random_town(int count, double size, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-0.5, 0.5), h(0.01, 0.2), w(0.005, 0.03);
    Scene scene;
    SceneObject ground;
    ground.shape = Shape::plane;
    ground.size = {size, 1.0, size};
    scene.objects.push_back(ground);
    for (int i = 0; i < count; ++i) {
        SceneObject box;
        box.size = {w(rng) * size, h(rng) * size, w(rng) * size};
        box.position = {u(rng) * size, box.size.y / 2, u(rng) * size};
        box.rotation_deg = {0.0, 360.0 * (u(rng) + 0.5), 0.0};
        scene.objects.push_back(box);
    }
    return scene;
}

inline bool finite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

inline bool in_unit_cube(const glm::dvec3& p, double tolerance) {
    return glm::all(glm::greaterThanEqual(p, glm::dvec3(-tolerance))) &&
           glm::all(glm::lessThanEqual(p, glm::dvec3(1.0 + tolerance)));
}

// Fallback texts every method may name (a prefix of the text).
inline bool is_named_fallback(const std::string& text) {
    for (const char* known : {"empty intersection body", "empty scene", "points behind the light",
                              "points outside the light's cone"})
        if (text.find(known) != std::string::npos) return true;
    return false;
}

}  // namespace shadowlab::testing
