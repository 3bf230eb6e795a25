#pragma once
// Node meshes as bytes, to carry them from the child process that read them (child_process) back to
// the program: a count, then per node its name, its vertices (three doubles each) and its triangles
// (three 32-bit indices each), its triangles' surfaces (TriangleSurface, none or one per
// triangle), its file's opacity maps (a count and texts), its file's material colours (a count, then
// each one's flag, colour and texture) and its count of broken faces dropped, in the machine's byte
// order (both ends are one program).
#include <optional>
#include <string>
#include <vector>

#include "scene/triangle_mesh.hpp"

namespace shadowlab {

std::string encode_node_meshes(const std::vector<NodeMesh>& nodes);

// The nodes back; nullopt when the bytes are cut short, run on, or name a vertex a node lacks.
std::optional<std::vector<NodeMesh>> decode_node_meshes(const std::string& bytes);

}  // namespace shadowlab
