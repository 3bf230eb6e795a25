#pragma once
// A scene around a lone mesh file (what the inspector opens when given an OBJ, PLY, STL or another
// format Assimp reads): the mesh framed by a camera looking down at it, under a sun that throws its
// shadow into view, on a ground that holds the shadow. glTF files have their own reader
// (gltf_scene), which borrows these parts when the file brings no camera or no light.
#include <string>

#include "geometry/aabb.hpp"
#include "scene/scene.hpp"

namespace shadowlab {

// Throws SceneError naming the file when the mesh cannot be loaded or has no triangles.
Scene scene_around_mesh(const std::string& mesh_file);

// Whether Assimp reads the file by its extension (a scene JSON is not a mesh).
bool is_mesh_file(const std::string& file);

// The parts, for meshes with these world bounds. Every place and length is taken from the bounds'
// sphere (its centre and radius), so that the parts move and scale with the meshes.
// The camera: from the front and a little to the right, looking down 30° at the sphere's centre,
// near enough that the sphere fills most of the narrower side of the view; its depth range holds
// the sphere and any ground ground_under gives.
Camera camera_framing(const Aabb& meshes);
// The sun: from behind the camera's left shoulder, 50° high, so that the shadows fall away from
// the camera and to its right, where the camera sees them.
Light sun_beside(const Camera& camera);
// The ground the meshes stand on, receiving only: it holds their footprint and their bounds'
// shadow under the light, with a margin, and reaches no farther than 3 radii from the centre (a
// low light's shadow runs off toward the horizon).
SceneObject ground_under(const Aabb& meshes, const Light& light);

}  // namespace shadowlab
