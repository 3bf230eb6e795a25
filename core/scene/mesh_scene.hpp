#pragma once
// A scene around a lone mesh file (what the inspector opens when given an OBJ, PLY, STL or glTF):
// the mesh on a ground plane, a camera looking at it from the front and above, a sun from above.
#include <string>

#include "scene/scene.hpp"

namespace shadowlab {

// Throws SceneError naming the file when the mesh cannot be loaded or has no triangles.
Scene scene_around_mesh(const std::string& mesh_file);

}  // namespace shadowlab
