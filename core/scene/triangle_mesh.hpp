#pragma once
// An indexed triangle mesh in an object's local space.
#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>
#include <glm/glm.hpp>

#include "geometry/aabb.hpp"
#include "notes/note.hpp"
#include "scene/alpha_test.hpp"
#include "scene/base_colour.hpp"

namespace shadowlab {

// A triangle's material and its corners' texture coordinates (TEXCOORD_0, v up as Assimp gives it),
// as the file gives them: what an alpha-tested material (scene/alpha_test.hpp) reads.
struct TriangleSurface {
    int material = -1;  // the file's material index; -1 for none
    std::array<glm::dvec2, 3> uv{};
};

// A material's colour as the file gives it (OBJ's Kd and map_Kd, the texture relative to the file's
// folder): what SceneObject::material_colour is made of (material_colours). Only a material the file
// names has one: Assimp's own (its "DefaultMaterial", an unnamed one for a format without materials)
// leaves the object its palette colour.
struct MaterialColourSource {
    bool named = false;
    glm::dvec3 diffuse{1.0};  // linear, as glTF's baseColorFactor
    std::string texture;      // empty for none
};

struct TriangleMesh {
    std::vector<glm::dvec3> vertices;
    std::vector<std::array<int, 3>> triangles;
    // Per triangle, parallel to `triangles`; empty when no mesh of the file has texture coordinates
    // (its triangles then have no surface to test: opaque).
    std::vector<TriangleSurface> surfaces;
    // Per material of the file (TriangleSurface::material): its opacity texture as the file names it
    // (OBJ's map_d, relative to the file's folder), empty for none; empty when no material has one.
    std::vector<std::string> opacity_maps;
    // Per material of the file: its colour; empty when no material of the file is named.
    std::vector<MaterialColourSource> colour_sources;
    std::size_t degenerate_dropped = 0;    // the file's zero-area triangles, left out of `triangles`
    std::size_t broken_faces_dropped = 0;  // faces naming a vertex their mesh lacks (as Assimp read them)

    Aabb bounds() const {
        Aabb box;
        for (const glm::dvec3& v : vertices) box.extend(v);
        return box;
    }
};

// Loads OBJ, PLY, STL, glTF or any format Assimp reads, all meshes of the file merged, zero-area
// triangles dropped (and counted). Assimp runs in a child process (assimp_reader, child_process), so
// a file it crashes or hangs on is refused like any other. Throws SceneError naming `json_path` and
// saying why when the file is missing or unreadable (Assimp's reason; "the importer crashed (signal
// 11, SIGSEGV)"; "the importer took over 60 s"), has a vertex that is not finite, or no triangle of
// non-zero area. Faces naming a vertex beyond their mesh (as Assimp reads some PLY files) are left
// out, counted, and said on stderr.
TriangleMesh load_triangle_mesh(const std::string& file, const std::string& scene_file, const std::string& json_path);

// A mesh file's path: a relative one is relative to the directory of the scene file naming it.
std::filesystem::path resolved_mesh_path(const std::string& file, const std::string& scene_file);

// The alpha tests of the file's materials with an opacity texture (OBJ's map_d: a PNG beside the file,
// its alpha channel or else its grey, kept at 0.5 and above; MTL has no cutoff), for
// SceneObject::material_alpha; null for the others, none when no material has one. A texture that is
// missing or not a PNG is a SceneError naming `json_path`, the mesh file and the texture.
std::vector<std::shared_ptr<const AlphaTest>> opacity_alpha_tests(const TriangleMesh& mesh, const std::string& file,
                                                                  const std::string& scene_file,
                                                                  const std::string& json_path);

// The base colours of the file's named materials (MaterialColourSource), for SceneObject::material_colour;
// null for the others, none when no material is named. A texture that is missing or not a PNG is a note
// in `notes` (base_colour_texture_missing: "quad.obj: map_Kd checker.png not found, its Kd shown"),
// naming the mesh file and the texture as the MTL does, the material then showing its Kd alone.
std::vector<std::shared_ptr<const BaseColour>> material_colours(const TriangleMesh& mesh, const std::string& file,
                                                                const std::string& scene_file,
                                                                std::vector<Note>& notes);

// What was left out of a file's meshes, for the user: "FILE: 3 faces name a vertex their mesh lacks
// (as Assimp reads them): left out" ("1 face names a vertex its mesh lacks"); empty when nothing
// was. Loading says it on stderr; the window shows it among its messages.
std::string broken_faces_note(const std::string& file, std::size_t broken_faces);

// The meshes one node of a file holds, together, placed in the file's world by the node's transform
// and its parents' (a glTF scene's objects, one per node).
struct NodeMesh {
    std::string node_name;  // as the file names the node; may be empty
    TriangleMesh mesh;
};

// The same file kept apart by node, in the file's node order (depth first); a node left with no
// triangle of non-zero area is left out. Refused as load_triangle_mesh refuses, when no node is left.
std::vector<NodeMesh> load_node_meshes(const std::string& file, const std::string& scene_file,
                                       const std::string& json_path);

}  // namespace shadowlab
