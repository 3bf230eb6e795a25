#pragma once
// What Assimp reads of a model file, positions only, kept apart by node and placed in the file's
// world. Assimp is asked for no post-processing step: its triangulation asserts and aborts on some
// files and its vertex joining crashes on others (Assimp 5.2), so faces are cut here
// (polygon_triangulation) and corners at one position joined here, per mesh. Every index and pointer
// of the structure Assimp returns is checked before it is followed; a face naming a vertex its mesh
// lacks is left out and counted. Quake 3 levels (.bsp, or packed in a .pk3) are read as Assimp's
// reader writes them: each face's corners are its three consecutive vertices, its index array
// unset. A child node Assimp left missing is passed over and the meshes no node placed are read
// unplaced. Fields a reader leaves unset read as zero (the child zero-fills the heap). Assimp itself can still crash
// or hang on a file: call this only inside a child process (child_process; triangle_mesh does).
#include <string>
#include <vector>

#include "scene/triangle_mesh.hpp"

namespace shadowlab {

struct AssimpRead {
    std::vector<NodeMesh> nodes;  // in the file's node order (depth first); nodes without a face left out
    std::string refusal;          // empty, or why the file gives no usable scene
    bool unreadable = false;      // the refusal is Assimp's: it read no scene at all
};

AssimpRead read_with_assimp(const std::string& path);

}  // namespace shadowlab
