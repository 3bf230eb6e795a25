#include "scene/triangle_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "io/value_text.hpp"
#include "scene/scene_error.hpp"

namespace shadowlab {
namespace {

// A relative mesh path is relative to the directory of the scene file that names it.
std::filesystem::path resolve(const std::string& file, const std::string& scene_file) {
    std::filesystem::path path(file);
    if (path.is_relative() && !scene_file.empty())
        path = std::filesystem::path(scene_file).parent_path() / path;
    return path.lexically_normal();
}

constexpr int kUnusedComponents =
    aiComponent_NORMALS | aiComponent_TANGENTS_AND_BITANGENTS | aiComponent_COLORS |
    aiComponent_TEXCOORDS | aiComponent_BONEWEIGHTS | aiComponent_ANIMATIONS |
    aiComponent_TEXTURES | aiComponent_LIGHTS | aiComponent_CAMERAS | aiComponent_MATERIALS;

glm::dvec3 to_dvec3(const aiVector3D& v) { return {v.x, v.y, v.z}; }

void append_mesh(const aiMesh& mesh, const aiMatrix4x4& transform, TriangleMesh& out) {
    if (!(mesh.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) return;  // only points or lines
    const int base = static_cast<int>(out.vertices.size());
    for (unsigned i = 0; i < mesh.mNumVertices; ++i)
        out.vertices.push_back(to_dvec3(transform * mesh.mVertices[i]));
    for (unsigned i = 0; i < mesh.mNumFaces; ++i) {
        const aiFace& face = mesh.mFaces[i];
        if (face.mNumIndices != 3) continue;  // a point or a line
        out.triangles.push_back({base + static_cast<int>(face.mIndices[0]),
                                 base + static_cast<int>(face.mIndices[1]),
                                 base + static_cast<int>(face.mIndices[2])});
    }
}

// Calls visit(node, its world transform) for every node, depth first, a parent before its children.
template <class Visit>
void visit_nodes(const aiNode& node, const aiMatrix4x4& parent, const Visit& visit) {
    const aiMatrix4x4 world_from_node = parent * node.mTransformation;
    visit(node, world_from_node);
    for (unsigned i = 0; i < node.mNumChildren; ++i) visit_nodes(*node.mChildren[i], world_from_node, visit);
}

void append_node_meshes(const aiScene& scene, const aiNode& node, const aiMatrix4x4& world_from_node,
                        TriangleMesh& out) {
    for (unsigned i = 0; i < node.mNumMeshes; ++i) append_mesh(*scene.mMeshes[node.mMeshes[i]], world_from_node, out);
}

// Why Assimp gave no usable scene: its own reason, or (its OBJ reader takes any text and finds
// nothing in it, saying nothing) what was seen.
std::string import_failure(const Assimp::Importer& importer, const aiScene* scene) {
    const std::string reason = importer.GetErrorString();
    if (!reason.empty()) return reason;
    return scene ? "no mesh in it (empty, or not a format Assimp recognises)" : "Assimp gives no reason";
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The first vertex of the file's meshes with a NaN or infinite coordinate, as the file gives it
// (a node transform would turn 0 * inf into NaN), e.g. "vertex 3 of mesh 0 is not finite: [0, inf,
// 0]"; empty when there is none.
std::string non_finite_vertex(const aiScene& scene) {
    for (unsigned m = 0; m < scene.mNumMeshes; ++m)
        for (unsigned i = 0; i < scene.mMeshes[m]->mNumVertices; ++i)
            if (const glm::dvec3 v = to_dvec3(scene.mMeshes[m]->mVertices[i]); !finite(v))
                return "vertex " + std::to_string(i) + " of mesh " + std::to_string(m) + " is not finite: " + value_text(v);
    return "";
}

// Zero area: two corners coincide, or the three lie on a line so exactly that the cross product
// of two edges is zero in double. Such a triangle has no normal for the tracer or the volumes.
bool degenerate(const TriangleMesh& mesh, const std::array<int, 3>& t) {
    const glm::dvec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    return glm::cross(b - a, c - a) == glm::dvec3(0.0);
}

void drop_degenerate(TriangleMesh& mesh) {
    const std::size_t before = mesh.triangles.size();
    std::erase_if(mesh.triangles, [&](const std::array<int, 3>& t) { return degenerate(mesh, t); });
    mesh.degenerate_dropped = before - mesh.triangles.size();
}

// Refusals name the scene file, the JSON path and the mesh file.
class MeshFileProblem {
public:
    MeshFileProblem(const std::filesystem::path& path, const std::string& scene_file, const std::string& json_path)
        : path_(path), scene_file_(scene_file), json_path_(json_path) {}

    [[noreturn]] void refuse(const std::string& problem) const {
        throw SceneError(scene_file_, json_path_, "mesh file " + path_.string() + ": " + problem);
    }
    [[noreturn]] void refuse_unread(const std::string& reason) const {
        throw SceneError(scene_file_, json_path_, "cannot read mesh file " + path_.string() + ": " + reason);
    }
    [[noreturn]] void refuse_missing() const {
        throw SceneError(scene_file_, json_path_, "mesh file not found: " + path_.string());
    }

    // Triangles placed, zero-area ones dropped; refused when a node transform overflowed a vertex.
    void check_placed_and_drop_degenerate(TriangleMesh& mesh) const {
        if (!std::all_of(mesh.vertices.begin(), mesh.vertices.end(), finite))
            refuse("a node transform takes a vertex beyond float's range");
        drop_degenerate(mesh);
    }
    // Why nothing is left: no triangles at all, or only zero-area ones.
    [[noreturn]] void refuse_empty(std::size_t degenerate_dropped) const {
        if (degenerate_dropped == 0) refuse("no triangles");
        refuse("no triangle with a non-zero area (" + std::to_string(degenerate_dropped) + " degenerate)");
    }

private:
    const std::filesystem::path& path_;
    const std::string& scene_file_;
    const std::string& json_path_;
};

// The file read through `importer` (which owns the result), only positions kept, so that corners
// differing in normal (STL) or uv are joined.
const aiScene& import_positions(Assimp::Importer& importer, const std::filesystem::path& path,
                                const MeshFileProblem& problem) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) problem.refuse_missing();
    importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, kUnusedComponents);
    const aiScene* scene =
        importer.ReadFile(path.string(), aiProcess_RemoveComponent | aiProcess_Triangulate |
                                             aiProcess_JoinIdenticalVertices);
    if (!scene || !scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
        problem.refuse_unread(import_failure(importer, scene));
    if (const std::string bad = non_finite_vertex(*scene); !bad.empty()) problem.refuse(bad);
    return *scene;
}

}  // namespace

TriangleMesh load_triangle_mesh(const std::string& file, const std::string& scene_file, const std::string& json_path) {
    const std::filesystem::path path = resolve(file, scene_file);
    const MeshFileProblem problem(path, scene_file, json_path);
    Assimp::Importer importer;
    const aiScene& scene = import_positions(importer, path, problem);
    TriangleMesh mesh;
    visit_nodes(*scene.mRootNode, aiMatrix4x4(), [&](const aiNode& node, const aiMatrix4x4& world_from_node) {
        append_node_meshes(scene, node, world_from_node, mesh);
    });
    if (mesh.triangles.empty()) problem.refuse_empty(0);
    problem.check_placed_and_drop_degenerate(mesh);
    if (mesh.triangles.empty()) problem.refuse_empty(mesh.degenerate_dropped);
    return mesh;
}

std::vector<NodeMesh> load_node_meshes(const std::string& file, const std::string& scene_file,
                                       const std::string& json_path) {
    const std::filesystem::path path = resolve(file, scene_file);
    const MeshFileProblem problem(path, scene_file, json_path);
    Assimp::Importer importer;
    const aiScene& scene = import_positions(importer, path, problem);
    std::vector<NodeMesh> nodes;
    std::size_t degenerate_dropped = 0;
    visit_nodes(*scene.mRootNode, aiMatrix4x4(), [&](const aiNode& node, const aiMatrix4x4& world_from_node) {
        NodeMesh placed{.node_name = node.mName.C_Str(), .mesh = {}};
        append_node_meshes(scene, node, world_from_node, placed.mesh);
        problem.check_placed_and_drop_degenerate(placed.mesh);
        degenerate_dropped += placed.mesh.degenerate_dropped;
        if (!placed.mesh.triangles.empty()) nodes.push_back(std::move(placed));
    });
    if (nodes.empty()) problem.refuse_empty(degenerate_dropped);
    return nodes;
}

}  // namespace shadowlab
