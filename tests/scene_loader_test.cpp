// Scene files: loading, defaults, every rejection, meshes, shipped scenes, and the camera frustum.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <string>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scene/scene_error.hpp"
#include "scene/scene_loader.hpp"

namespace shadowlab {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kFile = "test_scene.json";

fs::path source_path(const std::string& relative) { return fs::path(SHADOWLAB_SOURCE_DIR) / relative; }

fs::path write_temp(const std::string& name, const std::string& text) {
    const fs::path dir = fs::temp_directory_path() / "shadowlab_scene_test";
    fs::create_directories(dir);
    const fs::path path = dir / name;
    std::ofstream(path) << text;
    return path;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The smallest valid scene: a light and one object.
json minimal() { return json::parse(R"({"light": {"type": "directional"}, "objects": [{"type": "box"}]})"); }

// Checks that `run` throws a SceneError naming the file, the JSON path and the expectation.
template <class Run>
void expect_thrown(Run run, const std::string& file, const std::string& path, const std::string& expected) {
    try {
        run();
        ADD_FAILURE() << "accepted";
    } catch (const SceneError& error) {
        const std::string message = error.what();
        EXPECT_EQ(error.file(), file) << message;
        EXPECT_EQ(error.json_path(), path) << message;
        EXPECT_TRUE(contains(message, file) && contains(message, path)) << message;
        EXPECT_TRUE(contains(error.problem(), expected)) << message;
    }
}

void expect_text_error(const std::string& text, const std::string& path, const std::string& expected) {
    SCOPED_TRACE(text);
    expect_thrown([&] { parse_scene(text, kFile); }, kFile, path, expected);
}

void expect_error(const json& scene, const std::string& path, const std::string& expected) {
    expect_text_error(scene.dump(), path, expected);
}

// ---- accepted scenes -------------------------------------------------------------------------

TEST(SceneLoader, SmallestSceneGetsTheHeaderDefaults) {
    const Scene scene = parse_scene(minimal().dump(), kFile);
    const Camera camera;
    EXPECT_EQ(scene.name, "");
    EXPECT_EQ(scene.source_file, kFile);
    EXPECT_EQ(scene.camera.position, camera.position);
    EXPECT_EQ(scene.camera.target, camera.target);
    EXPECT_EQ(scene.camera.up, camera.up);
    EXPECT_EQ(scene.camera.fov_y_deg, camera.fov_y_deg);
    EXPECT_EQ(scene.camera.aspect, camera.aspect);
    EXPECT_EQ(scene.camera.near, camera.near);
    EXPECT_EQ(scene.camera.far, camera.far);
    EXPECT_EQ(scene.light.type, LightType::directional);
    EXPECT_NEAR(glm::length(scene.light.direction - glm::normalize(Light{}.direction)), 0.0, 1e-15);

    ASSERT_EQ(scene.objects.size(), 1u);
    const SceneObject& box = scene.objects[0];
    EXPECT_EQ(box.name, "box_0");
    EXPECT_EQ(box.shape, Shape::box);
    EXPECT_EQ(box.position, glm::dvec3(0.0));
    EXPECT_EQ(box.rotation_deg, glm::dvec3(0.0));
    EXPECT_EQ(box.scale, glm::dvec3(1.0));
    EXPECT_EQ(box.size, glm::dvec3(1.0));
    EXPECT_TRUE(box.casts);
    EXPECT_TRUE(box.receives);
}

TEST(SceneLoader, EmptyLightAndObjectAreDefaults) {
    const Scene scene = parse_scene(R"({"light": {}, "objects": [{}]})", kFile);
    EXPECT_EQ(scene.light.type, LightType::directional);
    EXPECT_EQ(scene.objects.at(0).shape, Shape::box);
}

TEST(SceneLoader, ReadsEveryField) {
    const Scene scene = parse_scene(R"({
        "name": "all", "description": "every field",
        "camera": {"position": [1, 2, 3], "target": [1, 2, -3], "up": [0, 2, 0],
                   "fov_y_deg": 45, "aspect": 1.5, "near": 0.25, "far": 50},
        "light": {"type": "spot", "direction": [0, -3, 0], "position": [0, 9, 0], "cone_deg": 40},
        "objects": [
            {"type": "plane", "name": "ground", "size": [20, 30], "casts": false},
            {"type": "sphere", "position": [1, 2, 3], "rotation": [10, 20, 30], "scale": 2,
             "radius": 0.75, "receives": false},
            {"type": "cylinder", "scale": [1, 2, 3], "radius": 0.5, "height": 4}]})",
                                    kFile);
    EXPECT_EQ(scene.name, "all");
    EXPECT_EQ(scene.camera.position, glm::dvec3(1, 2, 3));
    EXPECT_EQ(scene.camera.up, glm::dvec3(0, 1, 0));  // normalised
    EXPECT_EQ(scene.camera.fov_y_deg, 45.0);
    EXPECT_EQ(scene.camera.near, 0.25);
    EXPECT_EQ(scene.light.type, LightType::spot);
    EXPECT_EQ(scene.light.direction, glm::dvec3(0, -1, 0));  // normalised
    EXPECT_EQ(scene.light.position, glm::dvec3(0, 9, 0));
    EXPECT_EQ(scene.light.cone_deg, 40.0);

    ASSERT_EQ(scene.objects.size(), 3u);
    const SceneObject& ground = scene.objects[0];
    EXPECT_EQ(ground.name, "ground");
    EXPECT_EQ(ground.shape, Shape::plane);
    EXPECT_EQ(ground.size.x, 20.0);
    EXPECT_EQ(ground.size.z, 30.0);
    EXPECT_FALSE(ground.casts);
    const SceneObject& ball = scene.objects[1];
    EXPECT_EQ(ball.name, "sphere_1");
    EXPECT_EQ(ball.rotation_deg, glm::dvec3(10, 20, 30));
    EXPECT_EQ(ball.scale, glm::dvec3(2.0));
    EXPECT_EQ(ball.radius, 0.75);
    EXPECT_FALSE(ball.receives);
    const SceneObject& can = scene.objects[2];
    EXPECT_EQ(can.name, "cylinder_2");
    EXPECT_EQ(can.scale, glm::dvec3(1, 2, 3));
    EXPECT_EQ(can.height, 4.0);
}

TEST(SceneLoader, LoadsFromFile) {
    const fs::path path = write_temp("minimal.json", minimal().dump());
    const Scene scene = load_scene(path.string());
    EXPECT_EQ(scene.source_file, path.string());
    EXPECT_EQ(scene.objects.size(), 1u);
}

// ---- rejections ------------------------------------------------------------------------------

TEST(SceneRejects, MissingFile) {
    const std::string path = (fs::temp_directory_path() / "shadowlab_no_such_scene.json").string();
    expect_thrown([&] { load_scene(path); }, path, "", "cannot open file");
}

TEST(SceneRejects, MalformedJsonWithLineAndColumn) {
    expect_text_error("{\"light\": {},\n \"objects\": [{},]}", "", "malformed JSON at line 2, column 17");
    expect_text_error("", "", "malformed JSON at line 1, column 1");
}

TEST(SceneRejects, TopLevelNotAnObject) { expect_text_error("[1, 2]", "", "expected an object, got [1,2]"); }

TEST(SceneRejects, UnknownKeys) {
    json scene = minimal();
    scene["colour"] = "red";
    expect_error(scene, "colour", "allowed for a scene: name, description, camera, light, objects");

    scene = minimal();
    scene["camera"] = {{"fov", 60}};
    expect_error(scene, "camera.fov", "allowed for a perspective camera: projection, position, target, up, fov_y_deg");

    scene = minimal();
    scene["light"]["cone_deg"] = 30;
    expect_error(scene, "light.cone_deg", "allowed for a directional light: type, direction");

    scene = minimal();
    scene["objects"][0]["radius"] = 1;
    expect_error(scene, "objects[0].radius", "allowed for a box: type, name, position");
}

TEST(SceneRejects, StringWhereNumberExpected) {
    json scene = minimal();
    scene["camera"] = {{"near", "0.1"}};
    expect_error(scene, "camera.near", R"(expected a number, got "0.1")");
}

TEST(SceneRejects, ObjectWhereArrayExpected) {
    json scene = minimal();
    scene["objects"][0]["position"] = {{"x", 1}};
    expect_error(scene, "objects[0].position", R"(expected an array of three numbers, got {"x":1})");
}

TEST(SceneRejects, WrongArrayLength) {
    json scene = minimal();
    scene["light"]["direction"] = {0, -1};
    expect_error(scene, "light.direction", "expected an array of three numbers, got [0,-1]");

    scene = minimal();
    scene["objects"][0] = {{"type", "plane"}, {"size", {1, 2, 3}}};
    expect_error(scene, "objects[0].size", "expected an array of two numbers, got [1,2,3]");
}

TEST(SceneRejects, OtherWrongTypes) {
    json scene = minimal();
    scene["objects"][0]["casts"] = "yes";
    expect_error(scene, "objects[0].casts", R"(expected true or false, got "yes")");

    scene = minimal();
    scene["objects"][0]["name"] = 7;
    expect_error(scene, "objects[0].name", "expected a string, got 7");

    scene = minimal();
    scene["objects"][0]["scale"] = "big";
    expect_error(scene, "objects[0].scale", R"(expected a number or an array of three numbers)");

    scene = minimal();
    scene["light"] = "sun";
    expect_error(scene, "light", R"(expected an object, got "sun")");

    scene = minimal();
    scene["objects"] = {{"type", "box"}};
    expect_error(scene, "objects", "expected an array of objects");

    scene = minimal();
    scene["objects"][0] = 3;
    expect_error(scene, "objects[0]", "expected an object, got 3");
}

TEST(SceneRejects, InfiniteNumbers) {
    // nlohmann refuses 1e999 while parsing; the error still names the field.
    expect_text_error(R"({"camera": {"near": 1e999}, "light": {}, "objects": [{}]})", "camera.near",
                      "expected a finite number, got 1e999");
    expect_text_error(R"({"light": {}, "objects": [{}, {"size": [1, -1e999, 1]}]})", "objects[1].size[1]",
                      "expected a finite number, got -1e999");
}

TEST(SceneRejects, NanAndInfInMemory) {
    Scene scene = parse_scene(minimal().dump(), kFile);
    scene.camera.aspect = std::numeric_limits<double>::quiet_NaN();
    expect_thrown([&] { validate_scene(scene); }, kFile, "camera.aspect", "expected a finite number, got nan");

    scene = parse_scene(minimal().dump(), kFile);
    scene.objects[0].position.y = std::numeric_limits<double>::infinity();
    expect_thrown([&] { validate_scene(scene); }, kFile, "objects[0].position",
                  "expected three finite numbers, got [0, inf, 0]");
}

TEST(SceneRejects, NonPositiveSizes) {
    json scene = minimal();
    scene["objects"][0]["size"] = {1, -2, 1};
    expect_error(scene, "objects[0].size", "expected three positive numbers, got [1, -2, 1]");

    scene = minimal();
    scene["objects"][0] = {{"type", "plane"}, {"size", {10, 0}}};
    expect_error(scene, "objects[0].size", "expected two positive numbers, got [10, 0]");

    scene = minimal();
    scene["objects"][0] = {{"type", "sphere"}, {"radius", 0}};
    expect_error(scene, "objects[0].radius", "expected a positive number, got 0");

    scene = minimal();
    scene["objects"][0] = {{"type", "cylinder"}, {"height", -1}};
    expect_error(scene, "objects[0].height", "expected a positive number, got -1");
}

TEST(SceneRejects, NonPositiveScale) {
    json scene = minimal();
    scene["objects"][0]["scale"] = 0;
    expect_error(scene, "objects[0].scale", "expected three positive numbers, got [0, 0, 0]");

    scene["objects"][0]["scale"] = {1, -1, 1};
    expect_error(scene, "objects[0].scale", "expected three positive numbers, got [1, -1, 1]");
}

TEST(SceneRejects, NearNotPositive) {
    json scene = minimal();
    scene["camera"] = {{"near", 0}};
    expect_error(scene, "camera.near", "expected a positive number, got 0");
}

TEST(SceneRejects, NearNotBelowFar) {
    json scene = minimal();
    scene["camera"] = {{"near", 10}, {"far", 10}};
    expect_error(scene, "camera.far", "must be greater than near (10), got 10");
    scene["camera"]["far"] = 5;
    expect_error(scene, "camera.far", "must be greater than near (10), got 5");
}

TEST(SceneRejects, AspectNotPositive) {
    json scene = minimal();
    scene["camera"] = {{"aspect", -1.5}};
    expect_error(scene, "camera.aspect", "expected a positive number, got -1.5");
}

TEST(SceneRejects, FovOutOfRange) {
    for (double fov : {0.0, 180.0, -10.0, 200.0}) {
        json scene = minimal();
        scene["camera"] = {{"fov_y_deg", fov}};
        expect_error(scene, "camera.fov_y_deg", "expected an angle in (0, 180) degrees");
    }
}

TEST(SceneLoader, ReadsAnOrthographicCamera) {
    json scene = minimal();
    scene["camera"] = {{"projection", "orthographic"}, {"half_height", 12.5}, {"aspect", 2.0}};
    const Scene loaded = parse_scene(scene.dump(), kFile);
    EXPECT_EQ(loaded.camera.projection, CameraProjection::orthographic);
    EXPECT_EQ(loaded.camera.half_height, 12.5);
    EXPECT_EQ(loaded.camera.aspect, 2.0);
    EXPECT_EQ(parse_scene(minimal().dump(), kFile).camera.projection, CameraProjection::perspective);
}

TEST(SceneRejects, AnOrthographicCameraByItsOwnKeysAndHalfHeight) {
    json scene = minimal();
    scene["camera"] = {{"projection", "orthographic"}, {"fov_y_deg", 60}};
    expect_error(scene, "camera.fov_y_deg",
                 "allowed for an orthographic camera: projection, position, target, up, half_height");
    scene["camera"] = {{"projection", "fisheye"}};
    expect_error(scene, "camera.projection", R"(expected one of "perspective", "orthographic", got "fisheye")");
    for (double half_height : {0.0, -2.0}) {
        scene["camera"] = {{"projection", "orthographic"}, {"half_height", half_height}};
        expect_error(scene, "camera.half_height", "expected a positive number");
    }
    scene["camera"] = {{"projection", "orthographic"}, {"half_height", 1e13}};
    expect_error(scene, "camera.half_height", "expected a number within");
}

TEST(SceneRejects, ZeroLightDirection) {
    json scene = minimal();
    scene["light"]["direction"] = {0, 0, 0};
    expect_error(scene, "light.direction", "expected a non-zero direction, got [0, 0, 0]");
}

TEST(SceneRejects, CameraTargetAtPosition) {
    json scene = minimal();
    scene["camera"] = {{"position", {1, 2, 3}}, {"target", {1, 2, 3}}};
    expect_error(scene, "camera.target", "expected a point different from position");
}

TEST(SceneRejects, CameraUpParallelToView) {
    json scene = minimal();
    scene["camera"] = {{"position", {0, 5, 0}}, {"target", {0, 0, 0}}};
    expect_error(scene, "camera.up", "expected a direction not parallel to the view direction");
    scene["camera"]["up"] = {0, 0, 0};
    expect_error(scene, "camera.up", "expected a non-zero direction");
}

TEST(SceneRejects, ConeOutOfRange) {
    json scene = minimal();
    scene["light"] = {{"type", "spot"}, {"cone_deg", 180}};
    expect_error(scene, "light.cone_deg", "expected an angle in (0, 180) degrees, got 180");
}

TEST(SceneRejects, UnknownTypes) {
    json scene = minimal();
    scene["objects"][0]["type"] = "cube";
    expect_error(scene, "objects[0].type",
                 R"(expected one of "box", "sphere", "plane", "cylinder", "mesh", got "cube")");
    scene = minimal();
    scene["light"]["type"] = "sun";
    expect_error(scene, "light.type", R"(expected one of "directional", "spot", "point", got "sun")");
}

TEST(SceneRejects, MeshWithoutFile) {
    json scene = minimal();
    scene["objects"][0] = {{"type", "mesh"}};
    expect_error(scene, "objects[0].file", "required for a mesh, but missing");
}

TEST(SceneRejects, MissingMeshFile) {
    json scene = minimal();
    scene["objects"].push_back({{"type", "mesh"}, {"file", "meshes/none.obj"}});
    const std::string file = (fs::path("scenes") / "x.json").string();
    // Resolved relative to the scene file.
    expect_thrown([&] { parse_scene(scene.dump(), file); }, file, "objects[1].file",
                  "mesh file not found: scenes/meshes/none.obj");
}

// What follows "cannot read mesh file <path>: " when a scene names this mesh.
std::string refusal_reason(const fs::path& mesh) {
    json scene = minimal();
    scene["objects"][0] = {{"type", "mesh"}, {"file", mesh.string()}};
    try {
        parse_scene(scene.dump(), kFile);
    } catch (const SceneError& error) {
        const std::string prefix = "cannot read mesh file " + mesh.string() + ": ";
        EXPECT_EQ(error.json_path(), "objects[0].file") << error.what();
        EXPECT_EQ(error.problem().rfind(prefix, 0), 0u) << error.what();
        return error.problem().substr(std::min(prefix.size(), error.problem().size()));
    }
    ADD_FAILURE() << mesh << " accepted";
    return "";
}

TEST(SceneRejects, UnreadableMeshFileSaysWhy) {
    // Assimp's reason when it gives one (in its words)...
    EXPECT_FALSE(refusal_reason(write_temp("garbage.ply", "ply\nthis is not a mesh\n")).empty());
    // ...and when it gives none (its OBJ reader takes any text and finds nothing in it), ours.
    EXPECT_EQ(refusal_reason(write_temp("garbage.obj", "hello world\nthis is not a mesh\n")),
              "no mesh in it (empty, or not a format Assimp recognises)");
}

TEST(SceneRejects, MeshWithoutTriangles) {
    const fs::path mesh = write_temp("points.ply",
                                     "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                     "property float y\nproperty float z\nend_header\n"
                                     "0 0 0\n1 0 0\n0 1 0\n");
    // Assimp itself may refuse a file without faces; either way the file is named.
    expect_thrown([&] { load_triangle_mesh(mesh.string(), kFile, "objects[0].file"); }, kFile, "objects[0].file",
                  mesh.string());
}

// A tetrahedron whose vertex `bad` (0-based, as the file lists them) is replaced.
std::string tetrahedron_obj(int bad = -1, const std::string& replacement = "") {
    const std::string vertices[4] = {"v -0.5 0 -0.5", "v 0.5 0 -0.5", "v 0 0 0.5", "v 0 1 0"};
    std::string text;
    for (int i = 0; i < 4; ++i) text += (i == bad ? replacement : vertices[i]) + "\n";
    return text + "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";
}

TEST(SceneRejects, MeshWithANonFiniteVertex) {
    // 1e39 is beyond float: Assimp reads it as inf.
    const fs::path mesh = write_temp("inf_vertex.obj", tetrahedron_obj(3, "v 0 1e39 0"));
    expect_thrown([&] { load_triangle_mesh(mesh.string(), kFile, "objects[2].file"); }, kFile, "objects[2].file",
                  "mesh file " + mesh.string() + ": a vertex of mesh 0 is not finite: [0, inf, 0]");
}

TEST(SceneRejects, MeshWithOnlyZeroAreaTriangles) {
    const fs::path mesh = write_temp("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 2\n");
    expect_thrown([&] { load_triangle_mesh(mesh.string(), kFile, "objects[0].file"); }, kFile, "objects[0].file",
                  "no triangle with a non-zero area (2 degenerate)");
}

TEST(SceneRejects, EmptyObjects) {
    json scene = minimal();
    scene["objects"] = json::array();
    expect_error(scene, "objects", "expected at least one object, got none");
}

TEST(SceneRejects, MissingLightOrObjects) {
    json scene = minimal();
    scene.erase("light");
    expect_error(scene, "light", "required, but missing");
    scene = minimal();
    scene.erase("objects");
    expect_error(scene, "objects", "required, but missing");
}

TEST(SceneRejects, InMemorySceneByTheSameRules) {
    Scene scene;
    scene.objects.push_back(SceneObject{});
    EXPECT_NO_THROW(validate_scene(scene));
    scene.objects[0].size = {1, -2, 1};
    expect_thrown([&] { validate_scene(scene); }, "", "objects[0].size",
                  "expected three positive numbers, got [1, -2, 1]");

    scene.objects[0] = SceneObject{};
    scene.objects[0].shape = Shape::mesh;
    expect_thrown([&] { validate_scene(scene); }, "", "objects[0].file", "mesh not loaded");
}

// ---- ranges (limits.hpp) ------------------------------------------------------------------------

// The inputs that made Embree abort before the ranges: a camera far beyond float's reach, an aspect
// of 1e-308, and a light direction of 1e308 (a direction of any finite size is a direction: it is
// normalised without overflow).
TEST(SceneRanges, TheInputsThatAbortedAreRefusedOrNormalised) {
    json scene = minimal();
    scene["camera"] = {{"position", {1e30, 0, 0}}};
    expect_error(scene, "camera.position[0]", "expected a number within ±1e12, got 1e+30");

    scene = minimal();
    scene["camera"] = {{"aspect", 1e-308}};
    expect_error(scene, "camera.aspect", "expected a number within [0.001, 1000], got 1e-308");

    scene = minimal();
    scene["light"]["direction"] = {1e308, -1e308, 0};
    const glm::dvec3 direction = parse_scene(scene.dump(), kFile).light.direction;
    EXPECT_NEAR(glm::length(direction - glm::dvec3(std::sqrt(0.5), -std::sqrt(0.5), 0)), 0.0, 1e-15);
}

TEST(SceneRanges, PositionsWithinPlusMinus1e12) {
    json scene = minimal();
    scene["camera"] = {{"target", {0, 0, -2e12}}};
    expect_error(scene, "camera.target[2]", "expected a number within ±1e12, got -2000000000000");

    scene = minimal();
    scene["light"] = {{"type", "point"}, {"position", {0, 1e13, 0}}};
    expect_error(scene, "light.position[1]", "expected a number within ±1e12, got 10000000000000");

    scene = minimal();
    scene["objects"][0]["position"] = {0, 0, 1.5e12};
    expect_error(scene, "objects[0].position[2]", "expected a number within ±1e12, got 1500000000000");
}

TEST(SceneRanges, LengthsAndScalesWithinTheirRanges) {
    json scene = minimal();
    scene["objects"][0]["size"] = {1, 1e13, 1};
    expect_error(scene, "objects[0].size[1]", "expected a number within [1e-6, 1e12], got 10000000000000");

    scene = minimal();
    scene["objects"][0] = {{"type", "plane"}, {"size", {1e-7, 1}}};
    expect_error(scene, "objects[0].size[0]", "expected a number within [1e-6, 1e12], got 1e-07");

    scene = minimal();
    scene["objects"][0] = {{"type", "cylinder"}, {"radius", 1}, {"height", 1e-9}};
    expect_error(scene, "objects[0].height", "expected a number within [1e-6, 1e12], got 1e-09");

    scene = minimal();
    scene["objects"][0]["scale"] = {1, 2e6, 1};
    expect_error(scene, "objects[0].scale[1]", "expected a number within [1e-6, 1e6], got 2000000");

    scene = minimal();
    scene["camera"] = {{"near", 1e-7}};
    expect_error(scene, "camera.near", "expected a number within [1e-6, 1e12], got 1e-07");
}

TEST(SceneRanges, FarAtMost1e12AndAtMost1e9TimesNear) {
    json scene = minimal();
    scene["camera"] = {{"near", 1}, {"far", 2e9}};
    expect_error(scene, "camera.far", "must be at most 1e9 times near (1), got 2000000000");

    scene["camera"] = {{"near", 1e4}, {"far", 2e12}};
    expect_error(scene, "camera.far", "expected a number within [1e-6, 1e12], got 2000000000000");
}

// Each field within its range, the object reaches beyond ±1e12 once placed.
TEST(SceneRanges, EveryCornerOfAPlacedObjectWithinPlusMinus1e12) {
    json scene = minimal();
    scene["objects"][0]["position"] = {1e12, 0, 0};
    expect_error(scene, "objects[0]", "expected every corner within ±1e12 once placed");

    scene = minimal();
    scene["objects"][0]["scale"] = 1e6;
    scene["objects"][0]["size"] = {1, 1e7, 1};
    expect_error(scene, "objects[0]", "got a corner at 5000000000000");
}

TEST(SceneRanges, TheEndsOfEveryRangeAreAccepted) {
    json scene = minimal();
    scene["camera"] = {
        {"position", {-1e12, 0, 1e12}}, {"target", {0, 0, 0}}, {"aspect", 1e-3}, {"near", 1e-6}, {"far", 1}};
    scene["objects"] = json::parse(R"([{"size": [1e-6, 1e12, 1], "scale": [1e-6, 1e-6, 1e-6]},
                                       {"type": "sphere", "radius": 1, "scale": 1e6}])");
    EXPECT_NO_THROW(parse_scene(scene.dump(), kFile));
    scene["camera"]["aspect"] = 1e3;
    scene["camera"]["near"] = 1;
    scene["camera"]["far"] = 1e9;
    EXPECT_NO_THROW(parse_scene(scene.dump(), kFile));
}

TEST(SceneRanges, DirectionsOfAnyFiniteNonZeroSizeAreNormalised) {
    json scene = minimal();
    scene["camera"] = {{"up", {0, 1e-300, 0}}};
    scene["light"]["direction"] = {0, -5e-324, 0};
    const Scene loaded = parse_scene(scene.dump(), kFile);
    EXPECT_EQ(loaded.camera.up, glm::dvec3(0, 1, 0));
    EXPECT_EQ(loaded.light.direction, glm::dvec3(0, -1, 0));
}

TEST(SceneRejects, ShippedBadFilesMatchExpectedTsv) {
    const fs::path dir = source_path("tests/data/bad");
    std::ifstream tsv(dir / "EXPECTED.tsv");
    std::string line;
    std::set<std::string> listed;
    while (std::getline(tsv, line)) {
        const std::size_t tab = line.find('\t');
        ASSERT_NE(tab, std::string::npos) << line;
        const std::string file = line.substr(0, tab), expected = line.substr(tab + 1);
        listed.insert(file);
        try {
            load_scene((dir / file).string());
            ADD_FAILURE() << file << " accepted";
        } catch (const SceneError& error) {
            EXPECT_TRUE(contains(error.what(), file) && contains(error.what(), expected)) << error.what();
        }
    }
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() != ".json") continue;
        EXPECT_TRUE(listed.count(entry.path().filename().string())) << entry.path();
    }
    EXPECT_GE(listed.size(), 12u);
}

// ---- meshes ------------------------------------------------------------------------------------

class SceneMeshFormats : public testing::TestWithParam<std::string> {};

TEST_P(SceneMeshFormats, LoadsTheTetrahedron) {
    const std::string file = source_path("data/meshes/tetrahedron." + GetParam()).string();
    const TriangleMesh mesh = load_triangle_mesh(file, "", "file");
    EXPECT_EQ(mesh.triangles.size(), 4u);
    EXPECT_EQ(mesh.vertices.size(), 4u);  // STL's repeated corners joined
    const Aabb box = mesh.bounds();
    EXPECT_NEAR(glm::length(box.min - glm::dvec3(-0.5, 0.0, -0.5)), 0.0, 1e-6);
    EXPECT_NEAR(glm::length(box.max - glm::dvec3(0.5, 1.0, 0.5)), 0.0, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(SceneFormats, SceneMeshFormats, testing::Values("obj", "ply", "stl", "gltf"));

TEST(SceneMesh, ZeroAreaTrianglesAreDroppedAndCounted) {
    // Collinear corners, and a corner repeated.
    const fs::path path =
        write_temp("tetrahedron_and_slivers.obj", tetrahedron_obj() + "v 1 0 -0.5\nf 1 2 5\nf 4 4 2\n");
    const TriangleMesh mesh = load_triangle_mesh(path.string(), "", "file");
    EXPECT_EQ(mesh.triangles.size(), 4u);
    EXPECT_EQ(mesh.degenerate_dropped, 2u);
    EXPECT_EQ(load_triangle_mesh(source_path("data/meshes/tetrahedron.obj").string(), "", "file").degenerate_dropped,
              0u);
}

TEST(SceneMesh, NodeTransformsAreApplied) {
    std::ifstream in(source_path("data/meshes/tetrahedron.gltf"));
    json gltf = json::parse(in);
    gltf["nodes"] = json::parse(R"([{"children": [1, 2]}, {"mesh": 0},
                                    {"mesh": 0, "translation": [3, 0, 0]}])");
    const fs::path path = write_temp("two_tetrahedra.gltf", gltf.dump());
    const TriangleMesh mesh = load_triangle_mesh(path.string(), "", "file");
    EXPECT_EQ(mesh.triangles.size(), 8u);
    EXPECT_NEAR(mesh.bounds().max.x, 3.5, 1e-6);
    EXPECT_NEAR(mesh.bounds().min.x, -0.5, 1e-6);
}

TEST(SceneMesh, LoadedRelativeToTheSceneFileAndShared) {
    json scene = minimal();
    scene["objects"] = json::parse(R"([
        {"type": "mesh", "file": "../meshes/tetrahedron.stl", "scale": 2},
        {"type": "mesh", "file": "../meshes/tetrahedron.stl", "position": [5, 0, 0]}])");
    const Scene loaded = parse_scene(scene.dump(), source_path("data/scenes/in_memory.json").string());
    ASSERT_EQ(loaded.objects.size(), 2u);
    EXPECT_EQ(loaded.objects[0].mesh_file, "../meshes/tetrahedron.stl");
    EXPECT_EQ(loaded.objects[0].mesh, loaded.objects[1].mesh);
    EXPECT_NEAR(loaded.objects[0].world_bounds().max.y, 2.0, 1e-6);
    EXPECT_NEAR(loaded.objects[1].world_bounds().max.x, 5.5, 1e-6);
}

// ---- object bounds -----------------------------------------------------------------------------

TEST(SceneObjectBounds, LocalBoundsPerShape) {
    SceneObject object;
    object.size = {2, 4, 6};
    object.radius = 1.5;
    object.height = 3;
    const auto expect_local = [&](Shape shape, glm::dvec3 half) {
        object.shape = shape;
        EXPECT_EQ(object.local_bounds().min, -half) << to_string(shape);
        EXPECT_EQ(object.local_bounds().max, half) << to_string(shape);
    };
    expect_local(Shape::box, {1, 2, 3});
    expect_local(Shape::sphere, {1.5, 1.5, 1.5});
    expect_local(Shape::plane, {1, 0, 3});
    expect_local(Shape::cylinder, {1.5, 1.5, 1.5});
    object.shape = Shape::mesh;
    EXPECT_TRUE(object.local_bounds().empty());
}

TEST(SceneObjectBounds, WorldBoundsFollowTheModelMatrix) {
    SceneObject box;
    box.size = {2, 4, 6};
    box.scale = {2, 1, 1};
    box.rotation_deg = {0, 90, 0};  // scale first, then the yaw swaps x and z
    box.position = {10, 0, 0};
    const Aabb bounds = box.world_bounds();
    EXPECT_NEAR(glm::length(bounds.min - glm::dvec3(7, -2, -2)), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(bounds.max - glm::dvec3(13, 2, 2)), 0.0, 1e-12);

    Scene scene;
    scene.objects = {box, SceneObject{}};
    EXPECT_EQ(scene.bounds().min.x, -0.5);
    EXPECT_NEAR(scene.bounds().max.x, 13.0, 1e-12);
}

TEST(SceneObjectBounds, RotationOrderIsXThenYThenZ) {
    SceneObject object;
    object.rotation_deg = {90, 90, 0};
    // x first takes local +y to +z, then y takes +z to +x.
    const glm::dvec4 up = object.model_matrix() * glm::dvec4(0, 1, 0, 0);
    EXPECT_NEAR(glm::length(glm::dvec3(up) - glm::dvec3(1, 0, 0)), 0.0, 1e-12);
}

// ---- shipped scenes ----------------------------------------------------------------------------

double angle_deg(const glm::dvec3& a, const glm::dvec3& b) {
    return glm::degrees(std::acos(glm::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)));
}

Scene shipped(const std::string& name) { return load_scene(source_path("data/scenes/" + name + ".json").string()); }

TEST(SceneFiles, EveryShippedSceneLoads) {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(source_path("data/scenes"))) {
        if (entry.path().extension() != ".json") continue;
        SCOPED_TRACE(entry.path().string());
        const Scene scene = load_scene(entry.path().string());
        EXPECT_GE(scene.objects.size(), 2u);
        EXPECT_FALSE(scene.bounds().empty());
        EXPECT_LT(fs::file_size(entry.path()), 200u * 1024u);
        names.insert(entry.path().stem().string());
    }
    for (const char* name : {"default", "light_parallel_behind", "light_parallel_front", "casters_behind",
                             "light_overhead", "far_near_1e5", "box_on_plane", "spot", "point"})
        EXPECT_TRUE(names.count(name)) << name;
}

TEST(SceneFiles, ShippedScenesAreTheHardCasesTheyClaim) {
    const Scene town = shipped("default");
    EXPECT_GE(town.objects.size(), 350u);
    const glm::dvec3 to_sun = -town.light.direction;
    EXPECT_NEAR(angle_deg(to_sun, {to_sun.x, 0, to_sun.z}), 17.0, 3.0);  // a low sun

    const Scene behind = shipped("light_parallel_behind");
    EXPECT_NEAR(angle_deg(behind.light.direction, behind.camera.view_direction()), 1.0, 0.3);
    const Scene front = shipped("light_parallel_front");
    EXPECT_NEAR(angle_deg(front.light.direction, front.camera.view_direction()), 179.0, 0.3);
    const Scene overhead = shipped("light_overhead");
    EXPECT_NEAR(angle_deg(overhead.light.direction, overhead.camera.view_direction()), 90.0, 1e-9);
    const Scene deep = shipped("far_near_1e5");
    EXPECT_DOUBLE_EQ(deep.camera.far / deep.camera.near, 1e5);
    EXPECT_EQ(shipped("spot").light.type, LightType::spot);
    EXPECT_EQ(shipped("point").light.type, LightType::point);
}

// ---- camera and frustum ------------------------------------------------------------------------

Camera oblique_camera(double near, double far) {
    Camera camera;
    camera.position = {3, 4, 5};
    camera.target = {-1, 2, -7};
    camera.fov_y_deg = 50;
    camera.aspect = 1.5;
    camera.near = near;
    camera.far = far;
    return camera;
}

class SceneFrustum : public testing::TestWithParam<std::pair<double, double>> {
protected:
    Camera camera = oblique_camera(GetParam().first, GetParam().second);
    Frustum frustum = camera.frustum();
    double tolerance = 1e-9 * camera.far;
};

TEST_P(SceneFrustum, CornersLieOnTheirPlanes) {
    // Per plane (near, far, left, right, bottom, top), the corners on it.
    const int on_plane[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 3, 4, 7}, {1, 2, 5, 6}, {0, 1, 4, 5}, {2, 3, 6, 7}};
    for (int p = 0; p < 6; ++p)
        for (int c : on_plane[p])
            EXPECT_NEAR(frustum.planes[p].signed_distance(frustum.corners[c]), 0.0, tolerance)
                << "plane " << p << " corner " << c;
    for (const glm::dvec3& corner : frustum.corners) EXPECT_TRUE(frustum.contains(corner, tolerance));
}

TEST_P(SceneFrustum, CornerOrderFollowsTheImageAxes) {
    const glm::dvec3 right = glm::normalize(glm::cross(camera.view_direction(), camera.up));
    for (int base : {0, 4}) {
        EXPECT_GT(glm::dot(frustum.corners[base + 1] - frustum.corners[base], right), 0.0);
        EXPECT_GT(glm::dot(frustum.corners[base + 3] - frustum.corners[base], camera.up), 0.0);
    }
    const double far_half_height = std::tan(glm::radians(camera.fov_y_deg) / 2) * camera.far;
    EXPECT_NEAR(glm::length(frustum.corners[7] - frustum.corners[4]), 2 * far_half_height, tolerance);
    EXPECT_NEAR(glm::length(frustum.corners[5] - frustum.corners[4]), 2 * far_half_height * camera.aspect, tolerance);
}

TEST_P(SceneFrustum, ContainsTheMiddleAndExcludesOutsidePoints) {
    const glm::dvec3 eye = camera.position, view = camera.view_direction();
    EXPECT_TRUE(frustum.contains(eye + view * ((camera.near + camera.far) / 2)));
    EXPECT_TRUE(frustum.contains(eye + view * (camera.near * 1.01)));
    EXPECT_TRUE(frustum.contains(eye + view * (camera.far * 0.99)));
    EXPECT_FALSE(frustum.contains(eye - view));  // behind the camera
    EXPECT_FALSE(frustum.contains(eye + view * (camera.near * 0.5)));
    EXPECT_FALSE(frustum.contains(eye + view * (camera.far * 1.01)));
    const glm::dvec3 up = glm::normalize(glm::cross(glm::cross(view, camera.up), view));
    EXPECT_FALSE(frustum.contains(eye + view * 2.0 * camera.near + up * (2.0 * camera.near)));
}

INSTANTIATE_TEST_SUITE_P(SceneNearFar, SceneFrustum,
                         testing::Values(std::pair{0.1, 100.0}, std::pair{1e-3, 1e4}, std::pair{1.0, 1e7}));

TEST(SceneCamera, FrustumAgreesWithTheMatrices) {
    const Camera camera = oblique_camera(0.5, 40);
    const glm::dmat4 view_projection = camera.projection_matrix() * camera.view_matrix();
    const Frustum frustum = camera.frustum();
    for (int i = 0; i < 8; ++i) {
        const glm::dvec4 clip = view_projection * glm::dvec4(frustum.corners[i], 1.0);
        const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
        const int x = (i % 4 == 1 || i % 4 == 2) ? 1 : -1, y = (i % 4 >= 2) ? 1 : -1;
        EXPECT_NEAR(glm::length(ndc - glm::dvec3(x, y, i < 4 ? -1 : 1)), 0.0, 1e-9) << i;
    }
    const glm::dvec4 target = camera.view_matrix() * glm::dvec4(camera.target, 1.0);
    EXPECT_NEAR(target.x, 0.0, 1e-12);
    EXPECT_LT(target.z, 0.0);  // right-handed: the camera looks down -z
}

// ---- a light's range, and a light inside a caster (issue 14) ----------------------------------

TEST(SceneLoader, PointLightRangeIsReadAndChecked) {
    json scene = minimal();
    scene["light"] = {{"type", "point"}, {"position", {0, 5, 0}}, {"range", {0.5, 20}}};
    const Scene read = parse_scene(scene.dump(), kFile);
    ASSERT_TRUE(read.light.range.has_value());
    EXPECT_EQ(read.light.range->near, 0.5);
    EXPECT_EQ(read.light.range->far, 20.0);
    scene["light"]["range"] = {3, 3};
    expect_error(scene, "light.range[1]", "must be greater than near (3), got 3");
    scene["light"]["range"] = {4, 2};
    expect_error(scene, "light.range[1]", "must be greater than near (4), got 2");
    scene["light"]["range"] = {0, 0};
    expect_error(scene, "light.range", "expected two positive numbers, got [0, 0]");
    scene["light"]["range"] = {1};
    expect_error(scene, "light.range", "expected an array of two numbers");
    scene["light"] = {{"type", "directional"}, {"range", {1, 2}}};
    expect_error(scene, "light.range", "allowed for a directional light: type, direction");
}

// Inside a box, a sphere, a cylinder (each turned and scaled) or a closed mesh, the light is
// refused by name; beside them, or inside an object that casts nothing, it is not.
TEST(SceneLoader, ALightInsideACasterIsRefused) {
    const auto scene_with = [](const json& object, const json& light_position) {
        json scene = minimal();
        scene["light"] = {{"type", "point"}, {"position", light_position}};
        scene["objects"] = json::array({{{"type", "plane"}, {"size", {40, 40}}}, object});
        return scene;
    };
    const json box = {{"type", "box"}, {"position", {2, 1, 0}}, {"rotation", {0, 45, 0}}, {"size", {2, 2, 4}}};
    const json sphere = {{"type", "sphere"}, {"position", {0, 3, 0}}, {"radius", 1}, {"scale", {1, 2, 1}}};
    const json cylinder = {{"type", "cylinder"}, {"position", {0, 1, 0}}, {"radius", 0.5}, {"height", 2}};
    const json mesh = {{"type", "mesh"}, {"file", source_path("data/meshes/tetrahedron.obj").string()}, {"scale", 3}};
    for (const auto& [object, inside, outside] : {std::tuple{box, json{2.5, 1.0, 1.2}, json{3.9, 1.0, 0.0}},
                                                  std::tuple{sphere, json{0, 4.8, 0}, json{0.9, 4.8, 0}},
                                                  std::tuple{cylinder, json{0.3, 1.9, 0.3}, json{0.4, 1.0, 0.4}},
                                                  std::tuple{mesh, json{0.0, 0.3, 0.0}, json{5.0, 0.3, 0.0}}}) {
        expect_error(scene_with(object, inside), "light.position", "inside the caster objects[1]");
        EXPECT_NO_THROW(parse_scene(scene_with(object, outside).dump(), kFile)) << object.dump();
        json not_casting = object;
        not_casting["casts"] = false;
        EXPECT_NO_THROW(parse_scene(scene_with(not_casting, inside).dump(), kFile)) << object.dump();
    }
}

// Area lights: a sphere light's radius and the sun's angular radius, 0 (hard) by default; negative
// or too wide refused by field.
TEST(SceneLoader, AreaLightsAreReadAndChecked) {
    json scene = minimal();
    EXPECT_FALSE(parse_scene(scene.dump(), kFile).light.is_area());
    scene["light"] = {{"type", "directional"}, {"angular_radius_deg", 0.5}};
    EXPECT_EQ(parse_scene(scene.dump(), kFile).light.angular_radius_deg, 0.5);
    scene["light"]["angular_radius_deg"] = -0.1;
    expect_error(scene, "light.angular_radius_deg", "expected a number in [0, 45), got -0.1");
    scene["light"]["angular_radius_deg"] = 45;
    expect_error(scene, "light.angular_radius_deg", "expected a number in [0, 45), got 45");
    scene["light"] = {{"type", "point"}, {"position", {0, 5, 0}}, {"radius", 0.25}};
    EXPECT_TRUE(parse_scene(scene.dump(), kFile).light.is_area());
    scene["light"]["radius"] = -1;
    expect_error(scene, "light.radius", "expected a number in [0, 1e+12), got -1");
    scene["light"] = {{"type", "point"}, {"position", {0, 5, 0}}, {"angular_radius_deg", 1}};
    expect_error(scene, "light.angular_radius_deg", "allowed for a point light: type, position, range, radius");
}

}  // namespace
}  // namespace shadowlab
