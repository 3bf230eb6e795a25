// An engine's camera read back as the scene's: a Camera written as an OpenGL, Direct3D or Vulkan
// engine would write its view and projection, in every text form and storage, comes back as the
// same camera and the same world -> clip matrix, a pinhole or an orthographic one; what is neither is refused by name.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "exchange/camera_import.hpp"
#include "io/matrix_import.hpp"
#include "math/matrix.hpp"
#include "metrics/measurement.hpp"
#include "registry/method.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"
#ifdef SHADOWLAB_CLI
#include "cli_support.hpp"
#endif

namespace shadowlab {
namespace {

using testing::source_path;

// An engine's conventions and how it builds its projection from a camera's fov or half height, aspect, near, far.
struct Engine {
    std::string name;
    CameraConventions conventions;
    std::map<std::string, std::string> settings;  // the same conventions as the CLI names them
};

std::vector<Engine> engines() {
    std::vector<Engine> out;
    for (const bool reversed : {false, true}) {
        const std::string reversed_z = reversed ? "on" : "off";
        out.push_back({"OpenGL", {.reversed_z = reversed}, {{"reversed_z", reversed_z}}});
        out.push_back({"Direct3D",
                       {.depth = ClipDepth::zero_to_one, .reversed_z = reversed, .looks_along = EyeForward::plus_z},
                       {{"clip_depth", "zero_to_one"}, {"reversed_z", reversed_z}, {"looks_along", "plus_z"}}});
        out.push_back({"Vulkan",
                       {.depth = ClipDepth::zero_to_one, .reversed_z = reversed, .y = ClipY::down},
                       {{"clip_depth", "zero_to_one"}, {"reversed_z", reversed_z}, {"clip_y", "down"}}});
    }
    return out;
}

const glm::dmat4 kFlipZ = from_rows({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, -1, 0}, {0, 0, 0, 1});

// The view an engine of these conventions writes: Direct3D's left-handed eye space is OpenGL's
// mirrored in z (x right, y up, z ahead).
glm::dmat4 engine_view(const Camera& camera, const CameraConventions& c) {
    return (c.looks_along == EyeForward::plus_z ? kFlipZ : glm::dmat4(1.0)) * camera.view_matrix();
}

// The projection by the engines' own closed forms (glm::perspectiveRH_NO / _ZO, D3D's
// PerspectiveFovLH; glm::orthoRH_NO / _ZO, D3D's OrthographicLH): reversed Z swaps near and far;
// Vulkan negates the y row.
glm::dmat4 engine_projection(const Camera& camera, const CameraConventions& c) {
    const bool orthographic = camera.is_orthographic();
    const double f = orthographic ? 1.0 / camera.half_height : 1.0 / std::tan(glm::radians(camera.fov_y_deg) / 2.0);
    const double n = c.reversed_z ? camera.far : camera.near, r = c.reversed_z ? camera.near : camera.far;
    const glm::dvec4 depth =
        orthographic ? (c.depth == ClipDepth::minus_one_to_one ? glm::dvec4(0, 0, -2.0 / (r - n), -(r + n) / (r - n))
                                                               : glm::dvec4(0, 0, -1.0 / (r - n), -n / (r - n)))
        : c.depth == ClipDepth::minus_one_to_one ? glm::dvec4(0, 0, -(r + n) / (r - n), -2.0 * r * n / (r - n))
                                                 : glm::dvec4(0, 0, r / (n - r), -r * n / (r - n));
    const double y = c.y == ClipY::down ? -f : f;
    const glm::dvec4 w = orthographic ? glm::dvec4(0, 0, 0, 1) : glm::dvec4(0, 0, -1, 0);
    const glm::dmat4 right_handed = from_rows({f / camera.aspect, 0, 0, 0}, {0, y, 0, 0}, depth, w);
    return c.looks_along == EyeForward::plus_z ? right_handed * kFlipZ : right_handed;
}

std::string numbers_of(const glm::dmat4& m, MatrixStorage storage) {
    std::ostringstream out;
    out.precision(17);
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
            out << (a + b ? ", " : "") << (storage == MatrixStorage::column_major ? m[a][b] : m[b][a]);
    return out.str();
}

enum class TextForm { glsl, hlsl, json };

std::string camera_text(const glm::dmat4& view, const glm::dmat4& projection, MatrixStorage storage, TextForm form) {
    switch (form) {
        case TextForm::glsl:
            return "uniform mat4 viewMatrix = mat4(" + numbers_of(view, storage) + ");\n// the light's, passed over\n" +
                   "const mat4 lightViewProjection = mat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);\n" +
                   "uniform mat4 u_projection = mat4(" + numbers_of(projection, storage) + ");\n";
        case TextForm::hlsl:
            return "cbuffer Camera {\n    float4x4 g_View = {" + numbers_of(view, storage) +
                   "};\n    float4x4 g_Proj = {" + numbers_of(projection, storage) + "};\n};\n";
        case TextForm::json:
            return "{\"camera\": {\"view\": [" + numbers_of(view, storage) + "], \"projection\": [" +
                   numbers_of(projection, storage) +
                   "]},\n \"matrices\": [[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]]}";
    }
    return "";
}

std::string written_file(const std::string& name, const std::string& text) {
    const std::string file = ::testing::TempDir() + "camera_import_" + name;
    std::ofstream(file) << text;
    return file;
}

// Not aligned with any axis, up not perpendicular to the view, an aspect other than the default.
Camera engine_camera() {
    return {.position = {3.5, 2.25, 9.0},
            .target = {-1.0, 0.5, -2.0},
            .up = {0.1, 1.0, 0.05},
            .fov_y_deg = 47.0,
            .aspect = 1.6,
            .near = 0.3,
            .far = 250.0};
}

// The same pose seen orthographically, 2.5 units from the image's centre to its top.
Camera orthographic_engine_camera() {
    Camera camera = engine_camera();
    camera.projection = CameraProjection::orthographic;
    camera.half_height = 2.5;
    return camera;
}

void expect_relative(double a, double b, const std::string& what) {
    EXPECT_NEAR(a, b, 1e-9 * std::max(1.0, std::abs(b))) << what;
}

void expect_same_direction(const glm::dvec3& a, const glm::dvec3& b, const std::string& what) {
    EXPECT_LT(glm::length(glm::normalize(a) - glm::normalize(b)), 1e-9) << what;
}

// The camera's image up: its up made perpendicular to the view, as lookAt makes it.
glm::dvec3 image_up(const Camera& c) {
    const glm::dvec3 right = glm::cross(c.view_direction(), c.up);
    return glm::cross(right, c.view_direction());
}

void expect_same_camera(const Camera& imported, const Camera& camera, const std::string& what) {
    for (int i = 0; i < 3; ++i) expect_relative(imported.position[i], camera.position[i], what + ": position");
    expect_same_direction(imported.view_direction(), camera.view_direction(), what + ": view direction");
    expect_same_direction(imported.up, image_up(camera), what + ": up");
    EXPECT_EQ(imported.projection, camera.projection) << what;
    if (camera.is_orthographic())
        expect_relative(imported.half_height, camera.half_height, what + ": half height");
    else
        expect_relative(imported.fov_y_deg, camera.fov_y_deg, what + ": fov");
    expect_relative(imported.aspect, camera.aspect, what + ": aspect");
    expect_relative(imported.near, camera.near, what + ": near");
    expect_relative(imported.far, camera.far, what + ": far");
    const glm::dmat4 clip_from_world = camera.projection_matrix() * camera.view_matrix();
    const glm::dmat4 imported_clip_from_world = imported.projection_matrix() * imported.view_matrix();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            expect_relative(imported_clip_from_world[c][r], clip_from_world[c][r], what + ": world -> clip");
}

TEST(CameraImport, EveryEngineConventionRoundTrips) {
    const Aabb bounds{.min = {-5, 0, -5}, .max = {5, 2, 5}};
    for (const Camera& camera : {engine_camera(), orthographic_engine_camera()})
        for (const Engine& engine : engines())
            for (const MatrixStorage storage : {MatrixStorage::column_major, MatrixStorage::row_major})
                for (const TextForm form : {TextForm::glsl, TextForm::hlsl, TextForm::json}) {
                    CameraConventions conventions = engine.conventions;
                    conventions.storage = storage;
                    const std::string what = std::string(to_string(camera.projection)) + ", " + engine.name +
                                             (conventions.reversed_z ? " reversed Z" : "") +
                                             (storage == MatrixStorage::column_major ? ", by columns" : ", by rows") +
                                             ", form " + std::to_string(int(form));
                    const std::string text = camera_text(engine_view(camera, conventions),
                                                         engine_projection(camera, conventions), storage, form);
                    const Camera imported = camera_from_engine(parse_engine_camera(text, storage, "engine.txt"),
                                                               conventions, bounds, "engine.txt");
                    expect_same_camera(imported, camera, what);
                    expect_relative(glm::length(imported.target - imported.position),
                                    glm::length(bounds.center() - camera.position),
                                    what + ": target at the scene's centre");
                }
}

// Each text form read by its language's own order needs no storage named, and the conventions
// come from their CLI names.
TEST(CameraImport, AutomaticStorageAndNamedConventions) {
    const Camera camera = engine_camera();
    for (const Engine& engine : engines()) {
        const CameraConventions conventions = camera_conventions_from(engine.settings);
        const glm::dmat4 view = engine_view(camera, conventions), projection = engine_projection(camera, conventions);
        for (const auto& [form, storage] : {std::pair{TextForm::glsl, MatrixStorage::column_major},
                                            std::pair{TextForm::hlsl, MatrixStorage::row_major}}) {
            const std::string file = written_file(engine.name + ".txt", camera_text(view, projection, storage, form));
            expect_same_camera(import_camera(file, conventions, {}), camera, engine.name + " from " + file);
        }
    }
}

std::string refusal(const std::string& text, const std::map<std::string, std::string>& conventions = {}) {
    try {
        const CameraConventions c = camera_conventions_from(conventions);
        camera_from_engine(parse_engine_camera(text, c.storage, "engine.json"), c, {}, "engine.json");
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(accepted)";
}

// A matrix as JSON's 4 rows of 4, which need no storage named.
std::string json_rows(const glm::dmat4& m) {
    std::ostringstream out;
    out.precision(17);
    for (int r = 0; r < 4; ++r)
        out << (r ? ", [" : "[[") << m[0][r] << ", " << m[1][r] << ", " << m[2][r] << ", " << m[3][r] << "]";
    return out.str() + "]";
}

std::string json_camera(const glm::dmat4& view, const glm::dmat4& projection) {
    return "{\"camera\": {\"view\": " + json_rows(view) + ", \"projection\": " + json_rows(projection) + "}}";
}

TEST(CameraImport, WhatIsNotAPinholeIsRefusedNamingTheField) {
    const Camera camera = engine_camera();
    const glm::dmat4 view = camera.view_matrix(), projection = camera.projection_matrix();
    const glm::dmat4 skew = from_rows({1, 0.2, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1});
    glm::dmat4 singular = projection;
    singular[2] = singular[3];  // the eye's z taken as 1: every point of a view ray lands on one clip point
    glm::dmat4 off_centre = projection;
    off_centre[2][0] = 0.1;  // x / w shifted by the eye's depth
    glm::dmat4 infinite = projection;
    infinite[2][2] = -1.0, infinite[3][2] = -2.0 * camera.near;  // glm::infinitePerspective's depth row
    const glm::dmat4 orthographic_off_centre = glm::ortho(-3.0, 5.0, -2.5, 2.5, 0.3, 250.0);
    const glm::dmat4 orthographic_behind = glm::ortho(-4.0, 4.0, -2.5, 2.5, -1.0, 250.0);
    glm::dmat4 orthographic_oblique = glm::ortho(-4.0, 4.0, -2.5, 2.5, 0.3, 250.0);
    orthographic_oblique[2][0] = 0.1;  // x shifted by the eye's depth: an oblique (cabinet) projection
    const glm::dmat4 flip_y = from_rows({1, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1});
    for (const auto& [text, reason] : std::vector<std::pair<std::string, std::string>>{
             {json_camera(skew * view, projection),
              "engine.json: camera.view: not a rigid view: its 3x3 part is skewed"},
             {json_camera(2.0 * view, projection), "camera.view: not a view: its last row"},
             {json_camera(view, singular), "engine.json: camera.projection: singular matrix"},
             {json_camera(view, orthographic_off_centre), "camera.projection: off-centre view box (entry (0, 3)"},
             {json_camera(view, orthographic_oblique), "camera.projection: oblique: x depends on depth (entry (0, 2)"},
             {json_camera(view, orthographic_behind), "camera.projection: its depth puts the near plane at -1"},
             {json_camera(view, off_centre), "camera.projection: asymmetric (off-centre) frustum (entry (0, 2)"},
             {json_camera(view, infinite), "camera.projection: the far plane lies at infinity"},
             {json_camera(kFlipZ * view, projection * kFlipZ), "camera.view: a mirror (determinant -1)"},
             {json_camera(view, flip_y * projection), "camera.projection: the image is upside down"},
             {camera_text(view, projection, MatrixStorage::column_major, TextForm::json),
              "camera.view: 16 numbers in a row: name their storage"},
             {"{\"camera\": {\"view\": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]}}",
              "camera.projection: missing"},
             {"{\"matrices\": [[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]]}", "camera: expected"},
             {"{\"camera\": {}, \"lens\": 1}", "lens: unknown key"},
             {"uniform mat4 view = mat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);",
              "expected one matrix named for the view"},
         }) {
        const std::string message = refusal(text);
        EXPECT_NE(message.find(reason), std::string::npos) << text << "\n  gave: " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
    }
    // A convention that does not fit names the setting that would.
    const Engine vulkan = engines()[2];
    const std::string vulkan_text =
        json_camera(engine_view(camera, vulkan.conventions), engine_projection(camera, vulkan.conventions));
    EXPECT_NE(refusal(vulkan_text, {{"clip_depth", "zero_to_one"}}).find("set clip_y=down"), std::string::npos);
    const Engine direct3d = engines()[1];
    EXPECT_NE(
        refusal(json_camera(engine_view(camera, direct3d.conventions), engine_projection(camera, direct3d.conventions)),
                {{"clip_depth", "zero_to_one"}})
            .find("set looks_along=plus_z"),
        std::string::npos);
    const Engine reversed = engines()[3];
    EXPECT_NE(
        refusal(json_camera(engine_view(camera, reversed.conventions), engine_projection(camera, reversed.conventions)))
            .find("check clip_depth and reversed_z"),
        std::string::npos);
}

// One JSON file holds the light's matrices and the camera: each reader takes its own.
TEST(CameraImport, TheLightsMatricesMayShareTheFile) {
    const Camera camera = engine_camera();
    const std::string text =
        camera_text(camera.view_matrix(), camera.projection_matrix(), MatrixStorage::column_major, TextForm::json);
    EXPECT_EQ(parse_engine_matrices(text, MatrixStorage::column_major, "both.json").clip_from_world.size(), 1u);
    expect_same_camera(camera_from_engine(parse_engine_camera(text, MatrixStorage::column_major, "both.json"),
                                          {.storage = MatrixStorage::column_major}, {}, "both.json"),
                       camera, "both.json");
}

// The scene measured through the imported camera gives the numbers of the scene given that camera.
TEST(CameraImport, MeasuredAsTheSceneWithThatCamera) {
    Scene scene = load_scene(source_path("data/scenes/box_on_plane.json"));
    Camera camera = scene.camera;
    camera.position += glm::dvec3(1.5, 0.75, -0.5);
    camera.fov_y_deg *= 0.8;
    camera.aspect = 1.25;
    const CameraConventions direct3d = engines()[4].conventions;  // reversed Z
    const std::string file =
        written_file("measured.hlsl", camera_text(engine_view(camera, direct3d), engine_projection(camera, direct3d),
                                                  MatrixStorage::row_major, TextForm::hlsl));
    Scene given = scene, imported = scene;
    given.camera = camera;
    imported.camera = import_camera(file, direct3d, scene.bounds());
    const Method& method = method_or_throw("lispsm");
    const Settings settings = resolve_settings(method.name, method.settings, {});
    const Measurement a = measure(prepare_measurement(given, 160, 128), method, settings, 256, -1.0);
    const Measurement b = measure(prepare_measurement(imported, 160, 128), method, settings, 256, -1.0);
    EXPECT_GT(a.error.receiver_pixels, 0);
    EXPECT_EQ(a.error.receiver_pixels, b.error.receiver_pixels);
    EXPECT_EQ(a.error.misclassified, b.error.misclassified);
    expect_relative(b.error.m.mean, a.error.m.mean, "m mean");
}

#ifdef SHADOWLAB_CLI
// The command line: --camera-matrices replaces the scene file's camera.
TEST(CameraImport, MeasureTakesTheEngineCamera) {
    const std::string scene_file = source_path("data/scenes/box_on_plane.json");
    Camera camera = load_scene(scene_file).camera;
    camera.position += glm::dvec3(-1.0, 0.5, 0.5);
    camera.aspect = 1.5;
    const CameraConventions vulkan = engines()[5].conventions;  // reversed Z
    const std::string matrices =
        written_file("cli.glsl", camera_text(engine_view(camera, vulkan), engine_projection(camera, vulkan),
                                             MatrixStorage::column_major, TextForm::glsl));
    nlohmann::json scene = nlohmann::json::parse(testing::slurp(scene_file));
    scene["camera"] = {{"position", {camera.position.x, camera.position.y, camera.position.z}},
                       {"target", {camera.target.x, camera.target.y, camera.target.z}},
                       {"up", {camera.up.x, camera.up.y, camera.up.z}},
                       {"fov_y_deg", camera.fov_y_deg},
                       {"aspect", camera.aspect},
                       {"near", camera.near},
                       {"far", camera.far}};
    const std::string given_scene = written_file("given_scene.json", scene.dump());
    const std::string common = " --method focused --resolution 256 --size 192x128 --json";
    const testing::CliResult given = testing::run_cli("measure " + given_scene + common);
    const testing::CliResult imported =
        testing::run_cli("measure " + scene_file + common + " --camera-matrices " + matrices +
                         " --camera-conventions clip_depth=zero_to_one,reversed_z=on,clip_y=down");
    ASSERT_EQ(given.exit_code, 0) << given.err;
    ASSERT_EQ(imported.exit_code, 0) << imported.err;
    const nlohmann::json a = nlohmann::json::parse(given.out), b = nlohmann::json::parse(imported.out);
    for (const char* key : {"image", "receiver_pixels", "misclassified", "false_shadow", "false_light"})
        EXPECT_EQ(a[key], b[key]) << key;
    expect_relative(b["m"]["mean"].get<double>(), a["m"]["mean"].get<double>(), "m mean");

    const testing::CliResult wrong = testing::run_cli("measure " + scene_file + common + " --camera-matrices " +
                                                      matrices + " --camera-conventions clip_depth=zero_to_one");
    EXPECT_NE(wrong.exit_code, 0);
    EXPECT_NE(wrong.err.find(matrices + ": u_projection, matrix 2 (line 4): "), std::string::npos) << wrong.err;
}
#endif

}  // namespace
}  // namespace shadowlab
