#include "scene/triangle_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>

#include "scene/assimp_reader.hpp"
#include "scene/child_process.hpp"
#include "scene/file_bytes.hpp"
#include "scene/mesh_transfer.hpp"
#include "scene/png_alpha.hpp"
#include "scene/scene_error.hpp"

namespace shadowlab {
namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Zero area: two corners coincide, or the three lie on a line so exactly that the cross product
// of two edges is zero in double. Such a triangle has no normal for the tracer or the volumes.
bool degenerate(const TriangleMesh& mesh, const std::array<int, 3>& t) {
    const glm::dvec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    return glm::cross(b - a, c - a) == glm::dvec3(0.0);
}

void drop_degenerate(TriangleMesh& mesh) {
    const std::size_t before = mesh.triangles.size();
    std::size_t kept = 0;
    for (std::size_t i = 0; i < before; ++i) {  // the surfaces, when there are any, go with their triangles
        if (degenerate(mesh, mesh.triangles[i])) continue;
        mesh.triangles[kept] = mesh.triangles[i];
        if (!mesh.surfaces.empty()) mesh.surfaces[kept] = mesh.surfaces[i];
        ++kept;
    }
    mesh.triangles.resize(kept);
    if (!mesh.surfaces.empty()) mesh.surfaces.resize(kept);
    mesh.degenerate_dropped = before - kept;
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

// The child's answer: 'N' and the nodes, or 'U' (Assimp read nothing) or 'P' (what it read is
// unusable) and the reason.
std::string answer(const AssimpRead& read) {
    // Appended, not prefixed: GCC 12 warns falsely of overlap (-Wrestrict) in `"x" + std::string`.
    if (read.refusal.empty()) return std::string("N").append(encode_node_meshes(read.nodes));
    return std::string(read.unreadable ? "U" : "P").append(read.refusal);
}

// The file's nodes, read by Assimp in a child process: a crash, a hang or a runaway allocation there
// is this file's refusal, and the program goes on.
std::vector<NodeMesh> read_nodes(const std::filesystem::path& path, const MeshFileProblem& problem) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) problem.refuse_missing();
    const ChildResult child = run_in_child([&] { return answer(read_with_assimp(path.string())); });
    if (!child.ok()) problem.refuse_unread("the importer " + child.failure);
    const std::string reason = child.bytes.substr(std::min<std::size_t>(1, child.bytes.size()));
    if (child.bytes.starts_with('U')) problem.refuse_unread(reason);
    if (child.bytes.starts_with('P')) problem.refuse(reason);
    std::optional<std::vector<NodeMesh>> nodes = decode_node_meshes(reason);
    if (!child.bytes.starts_with('N') || !nodes) problem.refuse_unread("the importer's answer is garbled");
    std::size_t broken = 0;
    for (const NodeMesh& node : *nodes) broken += node.mesh.broken_faces_dropped;
    if (broken > 0) std::clog << broken_faces_note(path.string(), broken) << "\n";
    return std::move(*nodes);
}

}  // namespace

std::filesystem::path resolved_mesh_path(const std::string& file, const std::string& scene_file) {
    std::filesystem::path path(file);
    if (path.is_relative() && !scene_file.empty()) path = std::filesystem::path(scene_file).parent_path() / path;
    return path.lexically_normal();
}

std::vector<std::shared_ptr<const AlphaTest>> opacity_alpha_tests(const TriangleMesh& mesh, const std::string& file,
                                                                  const std::string& scene_file,
                                                                  const std::string& json_path) {
    constexpr double kOpacityCutoff = 0.5;
    const std::filesystem::path path = resolved_mesh_path(file, scene_file);
    const MeshFileProblem problem(path, scene_file, json_path);
    std::vector<std::shared_ptr<const AlphaTest>> tests;
    for (const std::string& map : mesh.opacity_maps) {
        if (map.empty()) {
            tests.push_back(nullptr);
            continue;
        }
        const std::filesystem::path texture = (path.parent_path() / map).lexically_normal();
        try {
            const std::string bytes = file_bytes(texture.string());
            tests.push_back(std::make_shared<const AlphaTest>(
                AlphaTest{.texture = std::make_shared<const AlphaTexture>(
                              decode_png_alpha(bytes, texture.string(), AlphaChannel::alpha_else_grey)),
                          .factor = 1.0,
                          .cutoff = kOpacityCutoff}));
        } catch (const SceneError&) {
            problem.refuse("map_d texture " + texture.string() + ": cannot open file");
        } catch (const std::invalid_argument& bad) {
            problem.refuse("map_d texture " + texture.string() + ": " + bad.what());
        }
    }
    return tests;
}

std::vector<std::shared_ptr<const BaseColour>> material_colours(const TriangleMesh& mesh, const std::string& file,
                                                                const std::string& scene_file,
                                                                std::vector<Note>& notes) {
    const std::filesystem::path path = resolved_mesh_path(file, scene_file);
    std::vector<std::shared_ptr<const BaseColour>> colours;
    for (const MaterialColourSource& source : mesh.colour_sources) {
        if (!source.named) {
            colours.push_back(nullptr);
            continue;
        }
        BaseColour colour{.factor = source.diffuse, .texture = nullptr};
        if (!source.texture.empty()) {
            std::string named = source.texture;  // an MTL written on Windows separates folders by '\\'
            std::replace(named.begin(), named.end(), '\\', '/');
            const std::filesystem::path texture = (path.parent_path() / named).lexically_normal();
            const std::string map_kd = path.filename().string() + ": map_Kd " + named;  // as messages name it
            try {
                colour.texture = std::make_shared<const ColourTexture>(
                    decode_colour_texture(file_bytes(texture.string()), texture.string()));
            } catch (const SceneError&) {
                notes.push_back({NoteKind::base_colour_texture_missing, map_kd + " not found, its Kd shown"});
            } catch (const std::invalid_argument& bad) {
                notes.push_back({NoteKind::base_colour_texture_missing, map_kd + ": " + bad.what() + ", its Kd shown"});
            }
        }
        colours.push_back(std::make_shared<const BaseColour>(std::move(colour)));
    }
    return colours;
}

std::string broken_faces_note(const std::string& file, std::size_t broken_faces) {
    if (broken_faces == 0) return "";
    const std::string faces = broken_faces == 1
                                  ? "1 face names a vertex its mesh lacks"
                                  : std::to_string(broken_faces) + " faces name a vertex their mesh lacks";
    return file + ": " + faces + " (as Assimp reads them): left out";
}

TriangleMesh load_triangle_mesh(const std::string& file, const std::string& scene_file, const std::string& json_path) {
    const std::filesystem::path path = resolved_mesh_path(file, scene_file);
    const MeshFileProblem problem(path, scene_file, json_path);
    TriangleMesh mesh;
    for (const NodeMesh& node : read_nodes(path, problem)) {
        const int base = static_cast<int>(mesh.vertices.size());
        mesh.vertices.insert(mesh.vertices.end(), node.mesh.vertices.begin(), node.mesh.vertices.end());
        if (!node.mesh.surfaces.empty()) mesh.surfaces.resize(mesh.triangles.size());  // the nodes before had none
        for (const std::array<int, 3>& t : node.mesh.triangles)
            mesh.triangles.push_back({base + t[0], base + t[1], base + t[2]});
        if (!node.mesh.surfaces.empty())
            mesh.surfaces.insert(mesh.surfaces.end(), node.mesh.surfaces.begin(), node.mesh.surfaces.end());
        else if (!mesh.surfaces.empty())
            mesh.surfaces.resize(mesh.triangles.size());
        mesh.broken_faces_dropped += node.mesh.broken_faces_dropped;
        mesh.opacity_maps = node.mesh.opacity_maps;  // the file's, the same in every node
        mesh.colour_sources = node.mesh.colour_sources;
    }
    if (mesh.triangles.empty()) problem.refuse_empty(0);
    problem.check_placed_and_drop_degenerate(mesh);
    if (mesh.triangles.empty()) problem.refuse_empty(mesh.degenerate_dropped);
    return mesh;
}

std::vector<NodeMesh> load_node_meshes(const std::string& file, const std::string& scene_file,
                                       const std::string& json_path) {
    const std::filesystem::path path = resolved_mesh_path(file, scene_file);
    const MeshFileProblem problem(path, scene_file, json_path);
    std::vector<NodeMesh> nodes;
    std::size_t degenerate_dropped = 0;
    for (NodeMesh& placed : read_nodes(path, problem)) {
        problem.check_placed_and_drop_degenerate(placed.mesh);
        degenerate_dropped += placed.mesh.degenerate_dropped;
        if (!placed.mesh.triangles.empty()) nodes.push_back(std::move(placed));
    }
    if (nodes.empty()) problem.refuse_empty(degenerate_dropped);
    return nodes;
}

}  // namespace shadowlab
