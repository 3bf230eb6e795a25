// Reading the models users bring: Assimp in a child process (a crash, a hang or a runaway
// allocation there is one file's refusal), the meshes carried back as bytes, faces cut and corners
// joined in our code, formats told by content, and messages that stay valid UTF-8.
#include <csignal>
#include <filesystem>
#include <fstream>
#include <random>
#include <thread>
#include <gtest/gtest.h>

#include "io/printable_text.hpp"
#include "scene/child_process.hpp"
#include "scene/mesh_transfer.hpp"
#include "scene/polygon_triangulation.hpp"
#include "scene/scene_error.hpp"
#include "scene/scene_loader.hpp"

namespace shadowlab {
namespace {

namespace fs = std::filesystem;

fs::path write_temp(const std::string& name, const std::string& bytes) {
    const fs::path dir = fs::temp_directory_path() / "shadowlab_mesh_import_test";
    fs::create_directories(dir);
    const fs::path path = dir / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

// The problem a load refuses the file with ("" when it loads).
std::string refusal(const fs::path& file) {
    try {
        load_scene(file.string());
    } catch (const SceneError& error) {
        return error.what();
    }
    return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

const std::string kTetrahedronObj = "v 0 0 0\nv 1 0 0\nv 0 0 1\nv 0 1 0\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";

// ---- the child process -----------------------------------------------------------------------

TEST(ChildProcess, ReturnsTheWorksBytes) {
    const ChildResult result = run_in_child([] { return std::string("answer\0with a zero", 18); });
    ASSERT_TRUE(result.ok()) << result.failure;
    EXPECT_EQ(result.bytes, std::string("answer\0with a zero", 18));
}

TEST(ChildProcess, ACrashIsNamedBySignalAndTheCallerGoesOn) {
    const ChildResult segv = run_in_child([]() -> std::string {
        std::raise(SIGSEGV);
        return "not reached";
    });
    EXPECT_EQ(segv.failure, "crashed (signal 11, SIGSEGV)");
    const ChildResult abort = run_in_child([]() -> std::string { std::abort(); });
    EXPECT_EQ(abort.failure, "crashed (signal 6, SIGABRT)");
}

TEST(ChildProcess, AHangIsKilledAtTheTimeLimit) {
    const auto start = std::chrono::steady_clock::now();
    const ChildResult result = run_in_child(
        [] {
            std::this_thread::sleep_for(std::chrono::seconds(30));
            return std::string("late");
        },
        {.seconds = 0.25});
    EXPECT_EQ(result.failure, "took over 0.25 s");
    // Killed, not waited for: well before the child's 30 s (a bound on behaviour, not speed).
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20));
}

TEST(ChildProcess, AnExceptionIsItsMessage) {
    const ChildResult result = run_in_child([]() -> std::string { throw std::runtime_error("no such thing"); });
    EXPECT_EQ(result.failure, "threw: no such thing");
}

TEST(ChildProcess, ARunawayAllocationMeetsTheMemoryLimit) {
    const ChildResult result = run_in_child(
        [] {
            std::vector<std::string> hoard;
            for (;;) hoard.emplace_back(std::size_t{64} << 20, 'x');  // 64 MiB at a time, touched
            return std::string("never");
        },
        {.seconds = 60.0, .extra_bytes = std::size_t{1} << 30});
    EXPECT_EQ(result.failure, "took over 1 GiB of memory");
}

// ---- the meshes as bytes ---------------------------------------------------------------------

std::vector<NodeMesh> two_nodes() {
    NodeMesh a{.node_name = "roof", .mesh = {}};
    a.mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0.5}};
    a.mesh.triangles = {{0, 1, 2}};
    NodeMesh b{.node_name = "", .mesh = {}};
    b.mesh.vertices = {{1e300, -2, 3}, {4, 5, 6}, {7, 8, 9}, {0.1, 0.2, 0.3}};
    b.mesh.triangles = {{0, 1, 2}, {2, 3, 0}};
    b.mesh.broken_faces_dropped = 3;
    return {a, b};
}

TEST(MeshTransfer, RoundTripsExactly) {
    const std::optional<std::vector<NodeMesh>> back = decode_node_meshes(encode_node_meshes(two_nodes()));
    ASSERT_TRUE(back);
    ASSERT_EQ(back->size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_EQ((*back)[i].node_name, two_nodes()[i].node_name);
        EXPECT_EQ((*back)[i].mesh.vertices, two_nodes()[i].mesh.vertices);
        EXPECT_EQ((*back)[i].mesh.triangles, two_nodes()[i].mesh.triangles);
        EXPECT_EQ((*back)[i].mesh.broken_faces_dropped, two_nodes()[i].mesh.broken_faces_dropped);
    }
}

// A node whose faces were all dropped has vertices and no triangle: the mesh fuzzer's finding of
// 2026-12-02 (a PLY whose face list was cut), where the empty list was copied from a null pointer.
TEST(MeshTransfer, RoundTripsANodeWithoutTriangles) {
    std::vector<NodeMesh> nodes = two_nodes();
    nodes[0].mesh.triangles.clear();
    nodes[0].mesh.broken_faces_dropped = 12;
    const std::optional<std::vector<NodeMesh>> back = decode_node_meshes(encode_node_meshes(nodes));
    ASSERT_TRUE(back);
    ASSERT_EQ(back->size(), 2u);
    EXPECT_TRUE((*back)[0].mesh.triangles.empty());
    EXPECT_EQ((*back)[0].mesh.vertices, nodes[0].mesh.vertices);
    EXPECT_EQ((*back)[0].mesh.broken_faces_dropped, 12u);
    EXPECT_EQ((*back)[1].mesh.triangles, nodes[1].mesh.triangles);
}

TEST(MeshTransfer, RefusesEveryCutAndEveryRunOn) {
    const std::string bytes = encode_node_meshes(two_nodes());
    for (std::size_t length = 0; length < bytes.size(); ++length)
        EXPECT_FALSE(decode_node_meshes(bytes.substr(0, length))) << "cut at " << length;
    EXPECT_FALSE(decode_node_meshes(bytes + "x"));
}

TEST(MeshTransfer, RefusesAnIndexBeyondTheVertices) {
    std::vector<NodeMesh> nodes = two_nodes();
    nodes[1].mesh.triangles[1][2] = 4;  // the node has 4 vertices
    EXPECT_FALSE(decode_node_meshes(encode_node_meshes(nodes)));
    nodes[1].mesh.triangles[1][2] = -1;
    EXPECT_FALSE(decode_node_meshes(encode_node_meshes(nodes)));
}

// ---- faces cut into triangles ----------------------------------------------------------------

// Twice the signed area of triangle t in the xz plane, seen from +y.
double twice_area(const std::vector<glm::dvec3>& v, const std::array<int, 3>& t) {
    const glm::dvec3 a = v[t[0]], b = v[t[1]], c = v[t[2]];
    return (b.z - a.z) * (c.x - a.x) - (b.x - a.x) * (c.z - a.z);
}

TEST(PolygonTriangulation, ConcaveFaceKeepsItsOutline) {
    // An L in the plane y = 1, counter-clockwise seen from +y; its area is 3. A fan from corner 0
    // would leave the notch covered.
    const std::vector<glm::dvec3> v = {{0, 1, 0}, {0, 1, 2}, {1, 1, 2}, {1, 1, 1}, {2, 1, 1}, {2, 1, 0}};
    const std::vector<int> corners = {3, 4, 5, 0, 1, 2};  // starts at the reflex corner's neighbour
    const std::vector<std::array<int, 3>> triangles = triangulate_polygon(v, corners);
    ASSERT_EQ(triangles.size(), 4u);
    double area = 0.0;
    for (const std::array<int, 3>& t : triangles) {
        EXPECT_GT(twice_area(v, t), 0.0) << "a triangle turned over";
        area += twice_area(v, t) / 2.0;
    }
    EXPECT_DOUBLE_EQ(area, 3.0);
}

TEST(PolygonTriangulation, ConvexFaceIsAFanFromItsFirstCorner) {
    const std::vector<glm::dvec3> v = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}, {-0.5, 0, 0.5}};
    const std::vector<int> corners = {0, 1, 2, 3, 4};
    const std::vector<std::array<int, 3>> expected = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}};
    EXPECT_EQ(triangulate_polygon(v, corners), expected);
}

TEST(PolygonTriangulation, ATwistedFaceStillGivesNMinusTwoTriangles) {
    // A bow tie: no ear survives, the rest is fanned.
    const std::vector<glm::dvec3> v = {{0, 0, 0}, {1, 0, 1}, {1, 0, 0}, {0, 0, 1}};
    EXPECT_EQ(triangulate_polygon(v, std::vector<int>{0, 1, 2, 3}).size(), 2u);
}

TEST(MeshImport, PolygonsAndSharedCornersAreReadInOurCode) {
    // A cube of six quads whose corners the file repeats per face, as STL and many exporters do.
    std::string obj;
    const int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
    int written = 0;
    for (const auto& face : faces) {
        for (int c : face)
            obj += "v " + std::to_string(corner[c][0]) + " " + std::to_string(corner[c][1]) + " " +
                   std::to_string(corner[c][2]) + "\n";
        obj += "f " + std::to_string(written + 1) + " " + std::to_string(written + 2) + " " +
               std::to_string(written + 3) + " " + std::to_string(written + 4) + "\n";
        written += 4;
    }
    const TriangleMesh mesh = load_triangle_mesh(write_temp("cube_of_quads.obj", obj).string(), "", "file");
    EXPECT_EQ(mesh.triangles.size(), 12u);
    EXPECT_EQ(mesh.vertices.size(), 8u);  // 24 corners in the file, 8 positions
}

TEST(MeshImport, AFaceNamingAMissingVertexIsLeftOutAndSaid) {
    const std::string ply =
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 2 9\n";
    const fs::path file = write_temp("missing_vertex.ply", ply);
    const TriangleMesh mesh = load_triangle_mesh(file.string(), "", "file");
    EXPECT_EQ(mesh.triangles.size(), 1u);
    EXPECT_EQ(mesh.broken_faces_dropped, 1u);
    const std::vector<std::string> notes = loading_notes(load_scene(file.string()));
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0], file.string() + ": 1 face names a vertex its mesh lacks (as Assimp reads them): left out");
}

// ---- formats by content, and messages --------------------------------------------------------

TEST(SceneFormats, AModelWithoutAnExtensionIsReadByItsContent) {
    const fs::path model = write_temp("tetrahedron_without_extension", kTetrahedronObj);
    EXPECT_EQ(refusal(model), "");
    EXPECT_EQ(load_scene(model.string()).objects.size(), 2u);  // the model and its ground
}

TEST(SceneFormats, AScenesJsonWithoutAnExtensionIsStillOne) {
    const fs::path scene = write_temp("scene_without_extension", "  {\"light\": 5}");
    EXPECT_TRUE(contains(refusal(scene), "light")) << refusal(scene);
}

TEST(SceneFormats, GltfOneIsNamed) {
    const fs::path file = write_temp("old.gltf", R"({"asset": {"version": "1.0"}, "scenes": {"s": {"nodes": []}}})");
    EXPECT_EQ(refusal(file), file.string() + ": asset.version: a glTF 1.0 file; ShadowLab reads glTF 2.0");
    const fs::path bare = write_temp("older.gltf", R"({"scenes": {"s": {"nodes": []}}, "nodes": {}})");
    EXPECT_EQ(refusal(bare), bare.string() + ": scenes: a glTF 1.0 file; ShadowLab reads glTF 2.0");
}

bool valid_utf8_without_controls(const std::string& text) { return printable_text(text) == text; }

TEST(PrintableText, KeepsUtf8AndEscapesTheRest) {
    EXPECT_EQ(printable_text("γ = 90°, ε²"), "γ = 90°, ε²");
    EXPECT_EQ(printable_text("a\nb\tc\x7F"), "a\\x0Ab\\x09c\\x7F");
    EXPECT_EQ(printable_text("\xC0\xAF"), "\\xC0\\xAF");                    // overlong '/'
    EXPECT_EQ(printable_text("\xED\xA0\x80"), "\\xED\\xA0\\x80");           // a surrogate
    EXPECT_EQ(printable_text("\xF4\x90\x80\x80"), "\\xF4\\x90\\x80\\x80");  // beyond U+10FFFF
    EXPECT_EQ(printable_text("\xE2\x82"), "\\xE2\\x82");                    // cut short
    EXPECT_EQ(printable_text("\xF0\x9F\x98\x80"), "\xF0\x9F\x98\x80");      // U+1F600 whole
}

TEST(PrintableText, ABinaryFilesMessageIsValidUtf8) {
    std::mt19937 rng(7);
    std::string bytes(4096, '\0');
    for (char& b : bytes) b = static_cast<char>(rng());
    const fs::path file = write_temp("binary.json", "{\"x\": \"" + bytes);
    const std::string message = refusal(file);
    ASSERT_FALSE(message.empty());
    EXPECT_TRUE(valid_utf8_without_controls(message)) << message;
    // And a model file of random bytes, whatever Assimp says of it.
    const std::string model_message = refusal(write_temp("binary.stl", bytes));
    EXPECT_TRUE(valid_utf8_without_controls(model_message)) << model_message;
}

}  // namespace
}  // namespace shadowlab
