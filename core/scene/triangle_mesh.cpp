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

void append_node(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent,
                 TriangleMesh& out) {
    const aiMatrix4x4 transform = parent * node.mTransformation;
    for (unsigned i = 0; i < node.mNumMeshes; ++i)
        append_mesh(*scene.mMeshes[node.mMeshes[i]], transform, out);
    for (unsigned i = 0; i < node.mNumChildren; ++i)
        append_node(scene, *node.mChildren[i], transform, out);
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

}  // namespace

TriangleMesh load_triangle_mesh(const std::string& file, const std::string& scene_file,
                                const std::string& json_path) {
    const std::filesystem::path path = resolve(file, scene_file);
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        throw SceneError(scene_file, json_path, "mesh file not found: " + path.string());

    Assimp::Importer importer;
    // Only positions are kept, so that corners differing in normal (STL) or uv are joined.
    importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, kUnusedComponents);
    const aiScene* scene =
        importer.ReadFile(path.string(), aiProcess_RemoveComponent | aiProcess_Triangulate |
                                             aiProcess_JoinIdenticalVertices);
    if (!scene || !scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
        throw SceneError(scene_file, json_path,
                         "cannot read mesh file " + path.string() + ": " + import_failure(importer, scene));

    const auto refuse = [&](const std::string& problem) {
        throw SceneError(scene_file, json_path, "mesh file " + path.string() + ": " + problem);
    };
    if (const std::string bad = non_finite_vertex(*scene); !bad.empty()) refuse(bad);
    TriangleMesh mesh;
    append_node(*scene, *scene->mRootNode, aiMatrix4x4(), mesh);
    if (mesh.triangles.empty()) refuse("no triangles");
    if (!std::all_of(mesh.vertices.begin(), mesh.vertices.end(), finite))
        refuse("a node transform takes a vertex beyond float's range");
    drop_degenerate(mesh);
    if (mesh.triangles.empty())
        refuse("no triangle with a non-zero area (" + std::to_string(mesh.degenerate_dropped) + " degenerate)");
    return mesh;
}

}  // namespace shadowlab
