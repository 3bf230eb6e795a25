// glTF scenes as they are: a file written here (gltf_support.hpp) opens with its own camera and light,
// placed by their nodes; another camera or light is chosen by number; what the file lacks is defaulted
// and said; a malformed file is refused in one line naming the file and the reason.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <nlohmann/json.hpp>

#include "gltf_support.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/mesh_scene.hpp"
#include "scene/scene_error.hpp"
#include "scene/scene_loader.hpp"

using namespace shadowlab;
using shadowlab::testing::kMainCameraTilt;
using shadowlab::testing::kSunTilt;
using shadowlab::testing::two_camera_scene;
using shadowlab::testing::write_test_file;

namespace {

constexpr double kTolerance = 1e-6;

void expect_near(const glm::dvec3& got, const glm::dvec3& expected) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], expected[i], kTolerance) << "component " << i;
}

// A node's −z and +y once turned by `degrees` about x.
glm::dvec3 ahead_after_tilt(double degrees) {
    return {0.0, std::sin(glm::radians(degrees)), -std::cos(glm::radians(degrees))};
}
glm::dvec3 up_after_tilt(double degrees) {
    return {0.0, std::cos(glm::radians(degrees)), std::sin(glm::radians(degrees))};
}

std::string written(const nlohmann::json& gltf, const std::string& name = "two_cameras.gltf") {
    return write_test_file(name, gltf.dump());
}

bool mentions(const std::vector<std::string>& lines, const std::string& word) {
    return std::any_of(lines.begin(), lines.end(),
                       [&](const std::string& line) { return line.find(word) != std::string::npos; });
}

// Refused with a SceneError on one line naming the file and saying `reason`.
void expect_refused(const std::string& file, const SceneChoice& choice, const std::string& reason) {
    try {
        load_scene(file, choice);
        ADD_FAILURE() << file << " accepted";
    } catch (const SceneError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find(file), std::string::npos) << message;
        EXPECT_NE(message.find(reason), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}
void expect_refused(const std::string& file, const std::string& reason) { expect_refused(file, {}, reason); }

}  // namespace

TEST(GltfScene, OpensWithItsFirstCameraAndItsSun) {
    const GltfScene gltf = read_gltf_scene(written(two_camera_scene()));
    const Camera& camera = gltf.scene.camera;
    expect_near(camera.position, {0.0, 3.0, 8.0});
    expect_near(camera.view_direction(), ahead_after_tilt(kMainCameraTilt));
    expect_near(glm::normalize(camera.up), up_after_tilt(kMainCameraTilt));
    EXPECT_NEAR(camera.fov_y_deg, 0.8 * 180.0 / std::numbers::pi, kTolerance);
    EXPECT_NEAR(camera.aspect, 1.5, kTolerance);
    EXPECT_NEAR(camera.near, 0.05, kTolerance);
    EXPECT_NEAR(camera.far, 200.0, kTolerance);

    const Light& sun = gltf.scene.light;
    EXPECT_EQ(sun.type, LightType::directional);
    expect_near(sun.direction, ahead_after_tilt(kSunTilt));
    EXPECT_TRUE(gltf.defaulted.empty()) << gltf.defaulted.front();
}

TEST(GltfScene, EachNodeIsAnObjectPlacedByItsTransformAndNoGroundIsAdded) {
    const Scene scene = read_gltf_scene(written(two_camera_scene())).scene;
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_EQ(scene.objects[0].name, "ground");
    EXPECT_EQ(scene.objects[1].name, "roof");
    const Aabb ground = scene.objects[0].world_bounds(), roof = scene.objects[1].world_bounds();
    expect_near(ground.min, {-10.0, 0.0, -10.0});
    expect_near(ground.max, {10.0, 0.0, 10.0});
    expect_near(roof.min, {-1.0, 2.0, -1.0});
    expect_near(roof.max, {1.0, 2.0, 1.0});
    for (const SceneObject& object : scene.objects) EXPECT_TRUE(object.casts && object.receives) << object.name;
}

TEST(GltfScene, TheChoiceGivesTheSecondCameraAndTheBulbAndNamesWhatItDefaulted) {
    const GltfScene gltf = read_gltf_scene(written(two_camera_scene()), {.camera = 1, .light = 1});
    const Camera& camera = gltf.scene.camera;
    expect_near(camera.position, {5.0, 1.0, 0.0});  // the rig's x, the camera's own y
    expect_near(camera.view_direction(), {-1.0, 0.0, 0.0});
    EXPECT_NEAR(camera.fov_y_deg, 0.5 * 180.0 / std::numbers::pi, kTolerance);
    EXPECT_NEAR(camera.near, 0.1, kTolerance);
    EXPECT_EQ(camera.aspect, Camera{}.aspect);
    // No zfar (an infinite far plane): twice the distance to the meshes' farthest corner, (−10, 2, ±10).
    EXPECT_NEAR(camera.far, 2.0 * glm::length(glm::dvec3(-10.0, 2.0, 10.0) - camera.position), kTolerance);
    EXPECT_TRUE(mentions(gltf.defaulted, "aspectRatio"));
    EXPECT_TRUE(mentions(gltf.defaulted, "zfar"));

    const Light& bulb = gltf.scene.light;
    EXPECT_EQ(bulb.type, LightType::point);
    expect_near(bulb.position, {1.0, 4.0, 1.0});
    ASSERT_TRUE(bulb.range.has_value());
    EXPECT_NEAR(bulb.range->far, 20.0, kTolerance);
    EXPECT_GT(bulb.range->near, 0.0);
}

TEST(GltfScene, LoadSceneTakesGltfByItsExtensionAndTheSameChoice) {
    const std::string file = written(two_camera_scene(), "TWO_CAMERAS.GLTF");
    const Scene chosen = load_scene(file, {.camera = 1, .light = 0});
    expect_near(chosen.camera.position, read_gltf_scene(file, {.camera = 1}).scene.camera.position);
    EXPECT_EQ(chosen.light.type, LightType::directional);
}

TEST(GltfScene, ASpotTakesItsOuterConeAsTheFullApexAngle) {
    nlohmann::json gltf = two_camera_scene();
    gltf["extensions"]["KHR_lights_punctual"]["lights"][1] = {{"type", "spot"}, {"spot", {{"outerConeAngle", 0.3}}}};
    const Light spot = read_gltf_scene(written(gltf), {.light = 1}).scene.light;
    EXPECT_EQ(spot.type, LightType::spot);
    EXPECT_NEAR(spot.cone_deg, 2.0 * 0.3 * 180.0 / std::numbers::pi, kTolerance);
    expect_near(spot.direction, {0.0, 0.0, -1.0});  // the bulb's node is not turned
    EXPECT_FALSE(spot.range.has_value());
}

TEST(GltfScene, WithoutCameraOrLightItIsAModelOnTheGroundUnderTheDefaultSun) {
    nlohmann::json gltf = two_camera_scene();
    gltf.erase("cameras");
    gltf.erase("extensions");
    for (nlohmann::json& node : gltf["nodes"]) {
        node.erase("camera");
        node.erase("extensions");
    }
    const GltfScene model = read_gltf_scene(written(gltf));
    ASSERT_EQ(model.scene.objects.size(), 3u);
    EXPECT_EQ(model.scene.objects[0].shape, Shape::plane);
    EXPECT_FALSE(model.scene.objects[0].casts);
    // Framed, lit and grounded as a lone mesh of the nodes' bounds is (mesh_scene_test pins those parts).
    Aabb nodes = model.scene.objects[1].world_bounds();
    nodes.extend(model.scene.objects[2].world_bounds());
    const Camera framing = camera_framing(nodes);
    expect_near(model.scene.camera.position, framing.position);
    expect_near(model.scene.camera.target, framing.target);
    expect_near(model.scene.light.direction, sun_beside(framing).direction);
    expect_near(model.scene.objects[0].size, ground_under(nodes, model.scene.light).size);
    EXPECT_TRUE(mentions(model.defaulted, "no camera"));
    EXPECT_TRUE(mentions(model.defaulted, "no KHR_lights_punctual light"));
}

TEST(GltfScene, WithACameraButNoLightTheSunStandsBehindThatCamera) {
    nlohmann::json gltf = two_camera_scene();
    gltf.erase("extensions");
    for (nlohmann::json& node : gltf["nodes"]) node.erase("extensions");
    const GltfScene scene = read_gltf_scene(written(gltf));
    expect_near(scene.scene.camera.position, {0.0, 3.0, 8.0});  // the file's
    expect_near(scene.scene.light.direction, sun_beside(scene.scene.camera).direction);
    EXPECT_TRUE(mentions(scene.defaulted, "no KHR_lights_punctual light"));
}

TEST(GltfScene, AnOrthographicCameraKeepsItsMagnificationsAndPlanes) {
    nlohmann::json gltf = two_camera_scene();
    gltf["cameras"][0] = {{"type", "orthographic"},
                          {"orthographic", {{"xmag", 3}, {"ymag", 1.5}, {"znear", 0.1}, {"zfar", 50}}}};
    const GltfScene scene = read_gltf_scene(written(gltf));
    const Camera& camera = scene.scene.camera;
    EXPECT_EQ(camera.projection, CameraProjection::orthographic);
    EXPECT_DOUBLE_EQ(camera.half_height, 1.5);
    EXPECT_DOUBLE_EQ(camera.aspect, 2.0);  // xmag / ymag
    EXPECT_DOUBLE_EQ(camera.near, 0.1);
    EXPECT_DOUBLE_EQ(camera.far, 50.0);
    expect_near(camera.view_direction(), ahead_after_tilt(kMainCameraTilt));
    EXPECT_EQ(scene.scene.objects.size(), 2u);  // the file has cameras: a scene, no ground added
}

// Khronos's Cameras sample (Assimp's corpus, scripts/setup.sh): camera 1 is orthographic, xmag = ymag =
// 1, znear 0.01, zfar 100, at (0.5, 0.5, 3) looking down -z at the square.
TEST(GltfScene, TheCamerasSamplesSecondCameraIsOrthographic) {
    const std::string file = "/usr/share/assimp/models/glTF2/cameras/Cameras.gltf";
    ASSERT_TRUE(std::filesystem::exists(file)) << file << " missing: install assimp-testmodels (scripts/setup.sh)";
    const Scene scene = load_scene(file, {.camera = 1});
    const Camera& camera = scene.camera;
    EXPECT_EQ(camera.projection, CameraProjection::orthographic);
    EXPECT_DOUBLE_EQ(camera.half_height, 1.0);
    EXPECT_DOUBLE_EQ(camera.aspect, 1.0);
    EXPECT_DOUBLE_EQ(camera.near, 0.01);
    EXPECT_DOUBLE_EQ(camera.far, 100.0);
    expect_near(camera.position, {0.5, 0.5, 3.0});
    expect_near(camera.view_direction(), {0.0, 0.0, -1.0});
    // Its view is the box |x - 0.5| <= 1, |y - 0.5| <= 1 from z = 2.99 down to z = -97.
    const Frustum box = camera.frustum();
    EXPECT_TRUE(box.contains({1.45, -0.45, -50.0}, kTolerance));
    EXPECT_FALSE(box.contains({1.55, 0.5, 0.0}, kTolerance));
    EXPECT_FALSE(box.contains({0.5, 0.5, 2.995}, kTolerance));
    EXPECT_EQ(load_scene(file, {.camera = 0}).camera.projection, CameraProjection::perspective);
}

TEST(GltfScene, ABinaryGlbOpensLikeItsJson) {
    nlohmann::json gltf = two_camera_scene();
    gltf["buffers"][0].erase("uri");                               // a .glb's buffer 0 is its BIN chunk
    const auto word = [](std::string& out, std::uint32_t value) {  // little-endian
        for (int i = 0; i < 4; ++i) out += static_cast<char>((value >> (8 * i)) & 0xFF);
    };
    std::string chunks;  // each: its length, its type, its data padded to 4 bytes
    const auto chunk = [&](std::string data, std::uint32_t type, char padding) {
        data.append((4 - data.size() % 4) % 4, padding);
        word(chunks, static_cast<std::uint32_t>(data.size()));
        word(chunks, type);
        chunks += data;
    };
    chunk(gltf.dump(), 0x4E4F534A, ' ');                         // "JSON"
    chunk(shadowlab::testing::quad_buffer(), 0x004E4942, '\0');  // "BIN"
    std::string glb;
    word(glb, 0x46546C67);  // "glTF"
    word(glb, 2);           // the version
    word(glb, static_cast<std::uint32_t>(12 + chunks.size()));
    glb += chunks;

    const Scene scene = load_scene(write_test_file("two_cameras.glb", glb));
    expect_near(scene.camera.position, {0.0, 3.0, 8.0});
    EXPECT_EQ(scene.objects.size(), 2u);
}

// ---- refusals --------------------------------------------------------------------------------

TEST(GltfSceneRejects, ACameraOrLightBeyondTheFilesByNumber) {
    const std::string file = written(two_camera_scene());
    expect_refused(file, {.camera = 2}, "camera 2 asked for, but the file holds 2 cameras (0 … 1)");
    expect_refused(file, {.light = 5}, "light 5 asked for, but the file holds 2 lights (0 … 1)");
    expect_refused(write_test_file("one.json", R"({"light": {}, "objects": [{}]})"), {.camera = 1},
                   "camera 1 asked for, but the file holds one camera (0)");
}

TEST(GltfSceneRejects, BrokenJsonWithItsLineAndColumn) {
    const std::string text = two_camera_scene().dump(2);
    expect_refused(write_test_file("broken.gltf", text.substr(0, text.size() / 2)), "malformed JSON");
}

TEST(GltfSceneRejects, ACameraWithANaN) {
    // JSON has no NaN; exporters that write one anyway write a bare NaN.
    std::string text = two_camera_scene().dump();
    const std::string yfov = "\"yfov\":0.8";
    text.replace(text.find(yfov), yfov.size(), "\"yfov\":NaN");
    expect_refused(write_test_file("nan_camera.gltf", text), "malformed JSON: parse error at line 1");
}

TEST(GltfSceneRejects, ACameraFieldOutOfRangeByItsPath) {
    nlohmann::json gltf = two_camera_scene();
    gltf["cameras"][1]["perspective"]["yfov"] = -0.5;
    expect_refused(written(gltf, "negative_fov.gltf"), {.camera = 1}, "cameras[1].perspective.yfov: expected an angle");
    gltf = two_camera_scene();
    gltf["cameras"][0]["perspective"]["zfar"] = 0.01;
    expect_refused(written(gltf, "far_before_near.gltf"),
                   "cameras[0].perspective.zfar: expected a distance beyond znear");
}

TEST(GltfSceneRejects, ALightOfAnUnknownType) {
    nlohmann::json gltf = two_camera_scene();
    gltf["extensions"]["KHR_lights_punctual"]["lights"][0]["type"] = "area";
    expect_refused(
        written(gltf, "area_light.gltf"),
        "extensions.KHR_lights_punctual.lights[0].type: expected \"directional\", \"point\" or \"spot\", got \"area\"");
}

TEST(GltfSceneRejects, AMissingBufferWithAssimpsReason) {
    nlohmann::json gltf = two_camera_scene();
    gltf["buffers"][0]["uri"] = "no_such_buffer.bin";
    expect_refused(written(gltf, "missing_buffer.gltf"), "cannot read mesh file");
}

TEST(GltfSceneRejects, ANodeThatIsItsOwnAncestor) {
    nlohmann::json gltf = two_camera_scene();
    gltf["nodes"][4]["children"] = nlohmann::json::array({3});
    expect_refused(written(gltf, "cycle.gltf"), "nodes[3]: reached twice");
}
