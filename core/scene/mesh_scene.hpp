#pragma once
// A scene around a lone mesh file (what the inspector opens when given an OBJ, PLY, STL or another
// format Assimp reads): the mesh on a ground plane, a camera looking at it from the front and above,
// a sun from above. glTF files have their own reader (gltf_scene), which borrows these parts when the
// file brings no camera or no light.
#include <string>

#include "geometry/aabb.hpp"
#include "scene/scene.hpp"

namespace shadowlab {

// Throws SceneError naming the file when the mesh cannot be loaded or has no triangles.
Scene scene_around_mesh(const std::string& mesh_file);

// Whether Assimp reads the file by its extension (a scene JSON is not a mesh).
bool is_mesh_file(const std::string& file);

// The parts, for meshes with these world bounds: the ground they stand on (four times their size,
// receiving only), a camera looking at them from the front and above, a sun from above.
SceneObject ground_under(const Aabb& meshes);
Camera camera_framing(const Aabb& meshes);
Light sun_from_above();

}  // namespace shadowlab
