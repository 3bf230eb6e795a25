#include "scene/triangle_mesh.hpp"

#include <filesystem>
#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

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
        throw SceneError(
            scene_file, json_path,
            "cannot read mesh file " + path.string() + ": " + importer.GetErrorString());

    TriangleMesh mesh;
    append_node(*scene, *scene->mRootNode, aiMatrix4x4(), mesh);
    if (mesh.triangles.empty())
        throw SceneError(scene_file, json_path, "mesh file has no triangles: " + path.string());
    return mesh;
}

}  // namespace shadowlab
