// A scene JSON referencing a glTF scene (gltf_reference): it picks one of the file's cameras and lights
// and marks objects, by name, as neither casting nor receiving, which the tessellation's caster flags
// and the object boxes carry on; the window's choices saved and loaded again come back the same; a
// name or a choice the file does not have is refused naming the JSON file and the JSON path.
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "gltf_support.hpp"
#include "methods/shadow_inputs.hpp"
#include "scene/gltf_reference.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/scene_error.hpp"
#include "scene/scene_loader.hpp"
#include "scene/tessellation.hpp"

using namespace shadowlab;
using shadowlab::testing::two_camera_scene;

namespace {

namespace fs = std::filesystem;

constexpr double kTolerance = 1e-9;
constexpr std::size_t kGround = 0, kRoof = 1;  // the objects of two_camera_scene, in its node order

// `text` in a fresh file at `relative` (sub-directories made) under this test process's own temporary
// directory (ctest runs tests in parallel processes: a shared one had a test read another's file).
std::string written(const fs::path& relative, const std::string& text) {
    const fs::path path = fs::path(::testing::TempDir()) / ("gltf_scene_json_" + std::to_string(::getpid())) / relative;
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
}

// The glTF scene, and a scene JSON one directory below it referencing it by a relative path.
struct Written {
    std::string gltf, json;
};
Written referencing(const nlohmann::json& reference) {
    const std::string gltf = written("two_cameras.gltf", two_camera_scene().dump());
    nlohmann::json root = reference;
    root["gltf"] = "../two_cameras.gltf";
    return {gltf, written("scenes/roofless.json", root.dump())};
}

void expect_near(const glm::dvec3& got, const glm::dvec3& expected) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], expected[i], kTolerance) << "component " << i;
}

// Refused with a SceneError naming `file` and `json_path` and saying `reason`, on one line.
void expect_refused(const std::string& file, const std::string& json_path, const std::string& reason) {
    try {
        load_scene(file);
        ADD_FAILURE() << file << " accepted";
    } catch (const SceneError& error) {
        EXPECT_EQ(error.file(), file);
        EXPECT_EQ(error.json_path(), json_path) << error.what();
        EXPECT_NE(error.problem().find(reason), std::string::npos) << error.what();
        EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos) << error.what();
    }
}

}  // namespace

TEST(GltfSceneJson, PicksTheSecondCameraAndMarksTheRoofNeitherCasterNorReceiver) {
    const Written files = referencing(
        {{"name", "roofless"}, {"camera", 1}, {"objects", {{"roof", {{"casts", false}, {"receives", false}}}}}});
    const Scene scene = load_scene(files.json);
    const Scene second_camera = read_gltf_scene(files.gltf, {.camera = 1}).scene;
    expect_near(scene.camera.position, second_camera.camera.position);
    expect_near(scene.camera.target, second_camera.camera.target);
    EXPECT_EQ(scene.light.type, LightType::directional);  // light 0, the sun, by default
    EXPECT_EQ(scene.name, "roofless");
    EXPECT_EQ(scene.source_file, files.json);

    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_EQ(scene.objects[kRoof].name, "roof");
    EXPECT_FALSE(scene.objects[kRoof].casts);
    EXPECT_FALSE(scene.objects[kRoof].receives);
    EXPECT_TRUE(scene.objects[kGround].casts && scene.objects[kGround].receives);

    // The roof is still drawn, but casts no shadow and is judged as no receiver.
    const WorldTriangles triangles = tessellate(scene);
    EXPECT_TRUE(std::count(triangles.object.begin(), triangles.object.end(), int(kRoof)) > 0);
    const std::vector<bool> casters = caster_flags(scene);
    EXPECT_FALSE(casters[kRoof]);
    EXPECT_TRUE(casters[kGround]);
    const std::vector<ObjectBox> boxes = object_boxes(scene);
    EXPECT_FALSE(boxes[kRoof].casts || boxes[kRoof].receives);
    EXPECT_TRUE(boxes[kGround].casts && boxes[kGround].receives);
}

TEST(GltfSceneJson, SavedChoicesAndRolesLoadBackTheSame) {
    const std::string gltf = written("two_cameras.gltf", two_camera_scene().dump());
    const SceneChoice choice{.camera = 1, .light = 1};
    Scene edited = read_gltf_scene(gltf, choice).scene;
    edited.objects[kRoof].casts = false;       // casts no shadow, still receives
    edited.objects[kGround].receives = false;  // casts, judged as no receiver
    const std::string json_file = written("saved/deeper/edited.json", "");
    save_scene_referencing_gltf(json_file, gltf, choice, edited);

    const nlohmann::json saved = nlohmann::json::parse(std::ifstream(json_file));
    EXPECT_FALSE(fs::path(saved["gltf"].get<std::string>()).is_absolute()) << saved.dump();

    const Scene loaded = load_scene(json_file);
    expect_near(loaded.camera.position, edited.camera.position);
    expect_near(loaded.camera.target, edited.camera.target);
    EXPECT_EQ(loaded.light.type, edited.light.type);
    expect_near(loaded.light.position, edited.light.position);
    ASSERT_EQ(loaded.objects.size(), edited.objects.size());
    for (std::size_t i = 0; i < loaded.objects.size(); ++i) {
        EXPECT_EQ(loaded.objects[i].casts, edited.objects[i].casts) << loaded.objects[i].name;
        EXPECT_EQ(loaded.objects[i].receives, edited.objects[i].receives) << loaded.objects[i].name;
    }
    const std::optional<GltfReference> reference = gltf_reference_of(json_file);
    ASSERT_TRUE(reference.has_value());
    EXPECT_TRUE(fs::equivalent(reference->gltf_file, gltf));
    EXPECT_EQ(reference->choice.camera, choice.camera);
    EXPECT_EQ(reference->choice.light, choice.light);
}

TEST(GltfSceneJson, OnlyAGltfFileOrAJsonReferencingOneStandsForAGltfScene) {
    const std::string gltf = written("two_cameras.gltf", two_camera_scene().dump());
    const std::optional<GltfReference> itself = gltf_reference_of(gltf, {.camera = 1});
    ASSERT_TRUE(itself.has_value());
    EXPECT_EQ(itself->gltf_file, gltf);
    EXPECT_EQ(itself->choice.camera, 1u);
    EXPECT_TRUE(itself->roles.empty());
    EXPECT_FALSE(gltf_reference_of(written("own.json", R"({"light": {}, "objects": [{}]})")).has_value());
}

TEST(GltfSceneJson, ObjectsSharingANameButNotTheirRolesAreNotSaved) {
    const std::string gltf = written("two_cameras.gltf", two_camera_scene().dump());
    Scene scene = read_gltf_scene(gltf).scene;
    scene.objects[kRoof].name = scene.objects[kGround].name;
    scene.objects[kRoof].casts = false;
    const std::string json_file = written("twins.json", "");
    try {
        save_scene_referencing_gltf(json_file, gltf, {}, scene);
        ADD_FAILURE() << "saved";
    } catch (const SceneError& error) {
        EXPECT_EQ(error.file(), json_file);
        EXPECT_EQ(error.json_path(), "objects.ground") << error.what();
    }
}

TEST(GltfSceneJson, AnObjectNameTheFileDoesNotHaveIsRefusedByItsPath) {
    expect_refused(referencing({{"objects", {{"chimney", {{"casts", false}}}}}}).json, "objects.chimney",
                   "no object of");
}

TEST(GltfSceneJson, ACameraOrLightBeyondTheFilesIsRefusedByItsPath) {
    expect_refused(referencing({{"camera", 2}}).json, "camera", "camera 2 asked for, but");
    expect_refused(referencing({{"light", 5}}).json, "light", "2 lights (0 … 1)");
}

TEST(GltfSceneJson, KeysAndTypesAreCheckedAsInEveryScene) {
    expect_refused(referencing({{"camera", 1.5}}).json, "camera", "expected an index");
    expect_refused(referencing({{"camera", -1}}).json, "camera", "expected an index");
    expect_refused(referencing({{"position", {0, 0, 0}}}).json, "position", "unknown key");
    expect_refused(referencing({{"objects", {{"roof", {{"cast", false}}}}}}).json, "objects.roof.cast", "unknown key");
    expect_refused(referencing({{"objects", {{"roof", {{"casts", 0}}}}}}).json, "objects.roof.casts",
                   "expected true or false");
    expect_refused(referencing({{"objects", nlohmann::json::array({"roof"})}}).json, "objects", "expected an object");
}

TEST(GltfSceneJson, ContentsNameEachCameraAndLightByItsOwnNameOrItsNodes) {
    nlohmann::json gltf = two_camera_scene();
    gltf["cameras"][1]["name"] = "close-up";
    const GltfContents contents = gltf_contents(written("named.gltf", gltf.dump()));
    ASSERT_EQ(contents.cameras.size(), 2u);
    EXPECT_EQ(contents.cameras[0].name, "main camera");  // the node holding it
    EXPECT_EQ(contents.cameras[1].name, "close-up");     // its own
    EXPECT_EQ(contents.cameras[0].type, "perspective");
    ASSERT_EQ(contents.lights.size(), 2u);
    EXPECT_EQ(contents.lights[0].name, "sun");
    EXPECT_EQ(contents.lights[0].type, "directional");
    EXPECT_EQ(contents.lights[1].name, "bulb");
    EXPECT_EQ(contents.lights[1].type, "point");
    EXPECT_EQ(contents.camera_choices(), 2u);
}
