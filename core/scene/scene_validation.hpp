#pragma once
// The numeric rules of a scene, whether read from a file (scene_loader.hpp applies them) or built in
// code or edited in the window (README.md, "Scene format"; the ranges are limits.hpp's): all numbers
// finite; positions within ±1e12, and so every corner of a placed object; sizes, radius, height,
// near, far and half_height in [1e-6, 1e12]; scale in [1e-6, 1e6]; aspect in [1e-3, 1e3];
// near < far <= 1e9 near; fov_y_deg and cone_deg in (0, 180); directions non-zero; camera target !=
// position and up not parallel to the view direction; a light range 0 < near < far within
// [1e-6, 1e12]; a spot or point light outside every caster (a map from inside a box sees only the box).
#include <cstddef>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace shadowlab {

// Checks the scene by those rules. Throws SceneError naming the scene's source file, the field's
// JSON path (camera.near, objects[2].scale) and what was expected.
void validate_scene(const Scene& scene);

// How the reader and the rules word what they expected: "a, b, c"; "three numbers", "a positive
// number", "two finite numbers".
std::string join(const std::vector<std::string>& items);
std::string count_of(std::size_t count, const std::string& adjective = "");

}  // namespace shadowlab
