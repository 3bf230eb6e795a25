#include "scene/assimp_reader.hpp"

#include <malloc.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <unordered_map>
#include <unordered_set>
#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/scene.h>

#include "io/value_text.hpp"
#include "scene/polygon_triangulation.hpp"

namespace shadowlab {
namespace {

// A node tree deeper than this, or with more nodes, is refused rather than walked.
constexpr std::size_t kMaxNodes = 1'000'000;

// The structure Assimp returned is not what it promises: the refusal says where.
struct Malformed {
    std::string what;
};

glm::dvec3 to_dvec3(const aiVector3D& v) { return {v.x, v.y, v.z}; }
bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string mesh_name(unsigned index) { return "mesh " + std::to_string(index); }

const aiMesh& checked_mesh(const aiScene& scene, unsigned index) {
    if (index >= scene.mNumMeshes || !scene.mMeshes || !scene.mMeshes[index])
        throw Malformed{"names " + mesh_name(index) + ", but the file holds " + std::to_string(scene.mNumMeshes)};
    const aiMesh& mesh = *scene.mMeshes[index];
    if (mesh.mNumVertices > 0 && !mesh.mVertices) throw Malformed{mesh_name(index) + " has no vertex array"};
    if (mesh.mNumFaces > 0 && !mesh.mFaces) throw Malformed{mesh_name(index) + " has no face array"};
    return mesh;
}

// The first vertex of the file's meshes with a NaN or infinite coordinate, as the file gives it
// (a node transform would turn 0 * inf into NaN), e.g. "a vertex of mesh 0 is not finite: [0, inf,
// 0]"; empty when there is none. Not numbered: without Assimp's vertex joining, its arrays hold a
// vertex per face corner for some formats (OBJ), so their index is not the file's.
std::string non_finite_vertex(const aiScene& scene) {
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh& mesh = checked_mesh(scene, m);
        for (unsigned i = 0; i < mesh.mNumVertices; ++i)
            if (const glm::dvec3 v = to_dvec3(mesh.mVertices[i]); !finite(v))
                return "a vertex of " + mesh_name(m) + " is not finite: " + value_text(v);
    }
    return "";
}

// One mesh's faces appended to `out`, its vertices placed by `world_from_node`; corners at one
// position in the file become one vertex (what aiProcess_JoinIdenticalVertices did), so that the
// volumes find the edges that faces share.
// How a mesh's faces name their corners: by their index arrays, or (Assimp 5.2's Quake 3 BSP reader
// writes each face's three corners as consecutive vertices and leaves the face's indices unset:
// heap garbage, out of range or not) as vertices 3f, 3f + 1, 3f + 2.
enum class Corners { indexed, consecutive };

Corners corners_of(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    return extension == ".pk3" || extension == ".bsp" ? Corners::consecutive : Corners::indexed;
}

// The corners of face f: its indices, or its consecutive vertices.
std::vector<unsigned> face_corners(const aiMesh& mesh, unsigned f, Corners corners) {
    const aiFace& face = mesh.mFaces[f];
    if (corners == Corners::consecutive) return {3 * f, 3 * f + 1, 3 * f + 2};
    return {face.mIndices, face.mIndices + face.mNumIndices};
}

// Each triangle's surface is kept where the mesh has texture coordinates or the file names its materials
// (their colours: MaterialColourSource), its coordinates (0, 0) where the mesh has none.
void append_mesh(const aiMesh& mesh, unsigned mesh_index, const aiMatrix4x4& world_from_node, Corners corners_are,
                 bool materials_named, TriangleMesh& out) {
    std::vector<glm::dvec3> placed(mesh.mNumVertices);
    for (unsigned i = 0; i < mesh.mNumVertices; ++i) placed[i] = to_dvec3(world_from_node * mesh.mVertices[i]);
    std::unordered_map<unsigned, int> welded_of_file;  // a file vertex -> its index in `out`
    std::unordered_map<std::size_t, std::vector<int>> by_position;
    const auto welded = [&](unsigned file_vertex) {
        if (const auto known = welded_of_file.find(file_vertex); known != welded_of_file.end()) return known->second;
        const aiVector3D& p = mesh.mVertices[file_vertex];
        const std::size_t key =
            std::hash<float>{}(p.x) ^ (std::hash<float>{}(p.y) << 1) ^ (std::hash<float>{}(p.z) << 2);
        for (int candidate : by_position[key])
            if (out.vertices[candidate] == placed[file_vertex]) return welded_of_file[file_vertex] = candidate;
        const int index = static_cast<int>(out.vertices.size());
        out.vertices.push_back(placed[file_vertex]);
        by_position[key].push_back(index);
        return welded_of_file[file_vertex] = index;
    };
    const aiVector3D* file_uvs = mesh.mNumVertices > 0 ? mesh.mTextureCoords[0] : nullptr;
    const bool surfaced = file_uvs || materials_named;
    if (surfaced) out.surfaces.resize(out.triangles.size());  // the meshes before it had none
    // The triangle's surface, kept parallel to the triangles once any mesh gave one.
    const auto add_surface = [&](const std::array<unsigned, 3>& file_corners) {
        if (!surfaced) {
            if (!out.surfaces.empty()) out.surfaces.emplace_back();
            return;
        }
        TriangleSurface surface{.material = static_cast<int>(mesh.mMaterialIndex), .uv = {}};
        if (file_uvs)
            for (int k = 0; k < 3; ++k) surface.uv[k] = {file_uvs[file_corners[k]].x, file_uvs[file_corners[k]].y};
        out.surfaces.push_back(surface);
    };
    std::vector<int> corners;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace& face = mesh.mFaces[f];
        if (face.mNumIndices < 3) continue;  // a point or a line casts no shadow
        if (!face.mIndices)
            throw Malformed{"face " + std::to_string(f) + " of " + mesh_name(mesh_index) + " has no corners"};
        const std::vector<unsigned> file_corners = face_corners(mesh, f, corners_are);
        if (std::any_of(file_corners.begin(), file_corners.end(), [&](unsigned c) { return c >= mesh.mNumVertices; })) {
            ++out.broken_faces_dropped;
            continue;
        }
        corners.clear();
        for (unsigned c : file_corners) corners.push_back(welded(c));
        if (corners.size() == 3) {
            out.triangles.push_back({corners[0], corners[1], corners[2]});
            add_surface({file_corners[0], file_corners[1], file_corners[2]});
            continue;
        }
        for (const std::array<int, 3>& t : triangulate_polygon(out.vertices, corners)) {
            out.triangles.push_back(t);
            std::array<unsigned, 3> of_file{};  // each welded corner's first place in the face
            for (int k = 0; k < 3; ++k)
                of_file[k] = file_corners[std::find(corners.begin(), corners.end(), t[k]) - corners.begin()];
            add_surface(of_file);
        }
    }
}

// Every node with its world transform, depth first, a parent before its children, each node once
// (a file whose tree loops back is read as a tree). A child Assimp left missing (its RAW reader
// allocates a child per mesh and fills fewer) is passed over; the meshes no node reached then
// follow as one more node, unplaced.
std::vector<NodeMesh> placed_nodes(const aiScene& scene, Corners corners, bool materials_named) {
    struct Pending {
        const aiNode* node;
        aiMatrix4x4 world_from_parent;
    };
    std::vector<Pending> stack{{scene.mRootNode, aiMatrix4x4()}};
    std::unordered_set<const aiNode*> seen;
    std::vector<bool> mesh_placed(scene.mNumMeshes, false);
    bool child_missing = false;
    std::vector<NodeMesh> nodes;
    const auto keep = [&](NodeMesh&& placed) {
        if (!placed.mesh.triangles.empty() || placed.mesh.broken_faces_dropped > 0) nodes.push_back(std::move(placed));
    };
    while (!stack.empty()) {
        const Pending pending = stack.back();
        stack.pop_back();
        if (!seen.insert(pending.node).second) continue;
        if (seen.size() > kMaxNodes) throw Malformed{"more than " + std::to_string(kMaxNodes) + " nodes"};
        const aiNode& node = *pending.node;
        const aiMatrix4x4 world_from_node = pending.world_from_parent * node.mTransformation;
        const std::string name = node.mName.C_Str();
        if (node.mNumMeshes > 0 && !node.mMeshes) throw Malformed{"node \"" + name + "\" has no mesh list"};
        if (node.mNumChildren > 0 && !node.mChildren) throw Malformed{"node \"" + name + "\" has no child list"};
        NodeMesh placed{.node_name = name, .mesh = {}};
        for (unsigned i = 0; i < node.mNumMeshes; ++i) {
            append_mesh(checked_mesh(scene, node.mMeshes[i]), node.mMeshes[i], world_from_node, corners,
                        materials_named, placed.mesh);
            mesh_placed[node.mMeshes[i]] = true;
        }
        keep(std::move(placed));
        for (unsigned i = node.mNumChildren; i-- > 0;) {  // pushed last first: visited in the file's order
            if (node.mChildren[i])
                stack.push_back({node.mChildren[i], world_from_node});
            else
                child_missing = true;
        }
    }
    if (child_missing) {
        NodeMesh unplaced{.node_name = "meshes without a node", .mesh = {}};
        for (unsigned m = 0; m < scene.mNumMeshes; ++m)
            if (!mesh_placed[m])
                append_mesh(checked_mesh(scene, m), m, aiMatrix4x4(), corners, materials_named, unplaced.mesh);
        keep(std::move(unplaced));
    }
    return nodes;
}

// Each material's opacity texture (OBJ's map_d) as the file names it, empty for none; none at all when
// no material has one.
std::vector<std::string> opacity_maps(const aiScene& scene) {
    std::vector<std::string> maps;
    for (unsigned m = 0; m < scene.mNumMaterials && scene.mMaterials; ++m) {
        aiString path;
        const aiMaterial* material = scene.mMaterials[m];
        const bool has = material && material->GetTexture(aiTextureType_OPACITY, 0, &path) == aiReturn_SUCCESS;
        maps.push_back(has ? path.C_Str() : "");
    }
    if (std::all_of(maps.begin(), maps.end(), [](const std::string& map) { return map.empty(); })) maps.clear();
    return maps;
}

// Each material's colour (OBJ's Kd and map_Kd: Assimp's diffuse colour and texture); none at all when the
// file names no material (Assimp's own default material, named "DefaultMaterial" or not at all, is none of
// the file's).
std::vector<MaterialColourSource> colour_sources(const aiScene& scene) {
    std::vector<MaterialColourSource> sources;
    for (unsigned m = 0; m < scene.mNumMaterials && scene.mMaterials; ++m) {
        MaterialColourSource& source = sources.emplace_back();
        const aiMaterial* material = scene.mMaterials[m];
        aiString name;
        if (!material || material->Get(AI_MATKEY_NAME, name) != aiReturn_SUCCESS || name.length == 0 ||
            std::string(name.C_Str()) == AI_DEFAULT_MATERIAL_NAME)
            continue;
        source.named = true;
        if (aiColor3D diffuse; material->Get(AI_MATKEY_COLOR_DIFFUSE, diffuse) == aiReturn_SUCCESS)
            source.diffuse = {diffuse.r, diffuse.g, diffuse.b};
        if (aiString path; material->GetTexture(aiTextureType_DIFFUSE, 0, &path) == aiReturn_SUCCESS)
            source.texture = path.C_Str();
    }
    if (std::none_of(sources.begin(), sources.end(), [](const auto& source) { return source.named; })) sources.clear();
    return sources;
}

// Why Assimp gave no usable scene: its own reason, or (its OBJ reader takes any text and finds
// nothing in it, saying nothing) what was seen.
std::string import_failure(const Assimp::Importer& importer, const aiScene* scene) {
    const std::string reason = importer.GetErrorString();
    if (!reason.empty()) return reason;
    return scene ? "no mesh in it (empty, or not a format Assimp recognises)" : "Assimp gives no reason";
}

}  // namespace

AssimpRead read_with_assimp(const std::string& path) {
    // Every block malloc gives is zero-filled from here on (glibc fills a new block with the
    // perturb byte ^ 0xFF): fields an Assimp reader leaves unset read as 0 and null, the same on
    // every run, rather than as what the heap held before (a wild pointer). Only the child process
    // that reads the file is affected.
    mallopt(M_PERTURB, 0xFF);
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, 0);  // no post-processing: see the header
    if (!scene || !scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || scene->mNumMeshes == 0)
        return {.nodes = {}, .refusal = import_failure(importer, scene), .unreadable = true};
    try {
        if (const std::string bad = non_finite_vertex(*scene); !bad.empty()) return {.nodes = {}, .refusal = bad};
        const std::vector<MaterialColourSource> colours = colour_sources(*scene);
        std::vector<NodeMesh> nodes = placed_nodes(*scene, corners_of(path), !colours.empty());
        const std::vector<std::string> maps = opacity_maps(*scene);
        for (NodeMesh& node : nodes) {
            node.mesh.opacity_maps = maps;
            node.mesh.colour_sources = colours;
        }
        return {.nodes = std::move(nodes), .refusal = {}};
    } catch (const Malformed& malformed) {
        return {.nodes = {}, .refusal = "Assimp's reading of it is malformed: " + malformed.what};
    }
}

}  // namespace shadowlab
