// Bring your own matrices: ShadowLab's own maps written the way OpenGL, Direct3D and Vulkan engines
// store them come back to the same world_to_uvz and the same measure; GLM's own projections land on
// the unit cube; a light box too small is reported; malformed text is refused with the reason.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>

#include "io/matrix_import.hpp"
#include "maps/clip_conventions.hpp"
#include "math/matrix.hpp"
#include "methods/map_coverage.hpp"
#include "metrics/measurement.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

using Conventions = std::map<std::string, std::string>;

// An engine: its clip space from ShadowLab's (u w, v w, d w, w), written from the engine's own
// definitions (not from uvz_from_clip), the way it writes a matrix down, and the settings naming it.
struct Engine {
    std::string name;
    glm::dmat4 (*clip_from_uvz_rows)(const glm::dvec4& u, const glm::dvec4& v, const glm::dvec4& d,
                                     const glm::dvec4& w);
    std::string (*written)(const glm::dmat4& clip_from_world);
    Conventions conventions;
};

std::string number(double x) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", x);
    return buffer;
}

// The 16 entries by columns or by rows, `suffix` after each number.
std::string entries(const glm::dmat4& m, bool by_columns, const std::string& suffix = "") {
    std::string out;
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) out += (a || b ? ", " : "") + number(by_columns ? m[a][b] : m[b][a]) + suffix;
    return out;
}

std::string json_rows(const glm::dmat4& m) {
    std::string out = "[";
    for (int r = 0; r < 4; ++r) {
        out += r ? ", [" : "[";
        for (int c = 0; c < 4; ++c) out += (c ? ", " : "") + number(m[c][r]);
        out += "]";
    }
    return out + "]";
}

// OpenGL: clip x, y, z in [-1, 1], v with y; a GLSL constant, column by column.
Engine opengl() {
    return {"OpenGL",
            [](const glm::dvec4& u, const glm::dvec4& v, const glm::dvec4& d, const glm::dvec4& w) {
                return from_rows(2.0 * u - w, 2.0 * v - w, 2.0 * d - w, w);
            },
            [](const glm::dmat4& m) {
                return "// the light's view-projection, as the renderer uploads it: mat4(1.0) is not it\n"
                       "uniform mat4 lightViewProjection;\nconst mat4 lightViewProjectionValue = mat4(" +
                       entries(m, true) + ");\n";
            },
            {}};
}

// Direct3D: z in [0, 1], texture v against clip y; an HLSL constant, row by row, float literals.
Engine direct3d() {
    return {"Direct3D",
            [](const glm::dvec4& u, const glm::dvec4& v, const glm::dvec4& d, const glm::dvec4& w) {
                return from_rows(2.0 * u - w, w - 2.0 * v, d, w);
            },
            [](const glm::dmat4& m) {
                return "cbuffer Shadow { float4x4 LightViewProj; };\nstatic const float4x4 LightViewProjValue = {" +
                       entries(m, false, "f") + "};\n";
            },
            {{"clip_depth", "zero_to_one"}, {"v_direction", "down"}}};
}

// Vulkan: z in [0, 1], y and v both down (so v with y); GLM's memory order in JSON.
Engine vulkan() {
    return {"Vulkan",
            [](const glm::dvec4& u, const glm::dvec4& v, const glm::dvec4& d, const glm::dvec4& w) {
                return from_rows(2.0 * u - w, 2.0 * v - w, d, w);
            },
            [](const glm::dmat4& m) { return "{\"matrices\": [[" + entries(m, true) + "]]}"; },
            {{"clip_depth", "zero_to_one"}, {"storage", "column_major"}}};
}

// Vulkan with reversed Z: z / w = 1 at the near plane, 0 at the far; JSON rows.
Engine vulkan_reversed_z() {
    return {"Vulkan reversed Z",
            [](const glm::dvec4& u, const glm::dvec4& v, const glm::dvec4& d, const glm::dvec4& w) {
                return from_rows(2.0 * u - w, 2.0 * v - w, w - d, w);
            },
            [](const glm::dmat4& m) { return "{\"matrices\": [" + json_rows(m) + "]}"; },
            {{"clip_depth", "zero_to_one"}, {"reversed_z", "on"}}};
}

std::vector<Engine> engines() { return {opengl(), direct3d(), vulkan(), vulkan_reversed_z()}; }

glm::dmat4 engine_matrix(const Engine& engine, const glm::dmat4& world_to_uvz) {
    const glm::dmat4& m = world_to_uvz;
    return engine.clip_from_uvz_rows(row(m, 0), row(m, 1), row(m, 2), row(m, 3));
}

std::string written_file(const std::string& name, const std::string& text) {
    std::string file = ::testing::TempDir() + "matrix_import_" + name;
    for (char& c : file)
        if (c == ' ') c = '_';
    std::ofstream(file) << text;
    return file;
}

Settings custom_settings_for(const std::string& file, Conventions conventions) {
    conventions["matrices"] = file;
    const Method& custom = method_or_throw("custom");
    return resolve_settings(custom.name, custom.settings, conventions);
}

ShadowSetup imported(const ShadowInputs& inputs, const std::string& file, const Conventions& conventions) {
    return method_or_throw("custom").compute_maps(inputs, custom_settings_for(file, conventions), nullptr);
}

Settings defaults(const std::string& method) {
    const Method& m = method_or_throw(method);
    return resolve_settings(m.name, m.settings, {});
}

ShadowSetup own_setup(const std::string& method, const ShadowInputs& inputs) {
    return method_or_throw(method).compute_maps(inputs, defaults(method), nullptr);
}

void expect_same_matrix(const glm::dmat4& a, const glm::dmat4& b, const std::string& what) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(a[c][r], b[c][r], 1e-9 * (1.0 + std::abs(b[c][r]))) << what;
}

const Scene& box_on_plane() {
    static const Scene scene = load_scene(source_path("data/scenes/box_on_plane.json"));
    return scene;
}

std::string refusal(const std::string& text, MatrixStorage storage = MatrixStorage::automatic) {
    try {
        parse_engine_matrices(text, storage, "engine.txt");
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(accepted)";
}

std::string mat4_of(const std::string& numbers) { return "const mat4 m = mat4(" + numbers + ");"; }

}  // namespace

TEST(MatrixImport, EachEnginesMatrixComesBackToTheSameMapAndTheSameMeasure) {
    const ShadowInputs inputs = gather_inputs(box_on_plane());
    const ShadowSetup focused = own_setup("focused", inputs);
    const MeasureContext context = prepare_measurement(box_on_plane(), 320, 180);
    const Measurement original = measure(context, method_or_throw("focused"), defaults("focused"), 512, -1.0);
    for (const Engine& engine : engines()) {
        const std::string file =
            written_file(engine.name, engine.written(engine_matrix(engine, focused.maps[0].world_to_uvz)));
        const ShadowSetup setup = imported(inputs, file, engine.conventions);
        ASSERT_EQ(setup.maps.size(), 1u) << engine.name;
        EXPECT_EQ(setup.selection.rule, MapSelection::Rule::only);
        expect_same_matrix(setup.maps[0].world_to_uvz, focused.maps[0].world_to_uvz, engine.name);
        // The focused map holds every visible receiver: nothing to report but, perhaps, its spare texels.
        EXPECT_FALSE(has_note(setup.fallbacks, NoteKind::missed_receivers)) << describe(setup.fallbacks);
        EXPECT_FALSE(has_note(setup.fallbacks, NoteKind::casters_before_near_plane)) << describe(setup.fallbacks);
        const Measurement custom =
            measure(context, method_or_throw("custom"), custom_settings_for(file, engine.conventions), 512, -1.0);
        // The text holds 17 digits: at most a pixel on a texel's edge may turn.
        EXPECT_NEAR(custom.error.misclassified, original.error.misclassified, 1.0 / original.error.receiver_pixels)
            << engine.name;
    }
}

// An atlas of cascades chosen by view depth: the tiles and split depths travel with the matrices.
TEST(MatrixImport, CascadesInAnAtlasComeBackWithTheirTilesAndSplits) {
    const ShadowInputs inputs = gather_inputs(box_on_plane());
    const ShadowSetup cascades = own_setup("cascades", inputs);
    ASSERT_GT(cascades.maps.size(), 1u);
    std::string matrices, tiles;
    for (const ShadowMap& map : cascades.maps) {
        matrices += (matrices.empty() ? "" : ", ") + json_rows(engine_matrix(opengl(), map.world_to_uvz));
        const glm::dvec4& t = map.viewport;
        tiles += (tiles.empty() ? "[" : ", [") + number(t.x) + ", " + number(t.y) + ", " + number(t.z) + ", " +
                 number(t.w) + "]";
    }
    std::string splits;
    for (double depth : cascades.selection.split_depths) splits += (splits.empty() ? "" : ", ") + number(depth);
    const std::string file = written_file("cascades.json", "{\"matrices\": [" + matrices + "], \"tiles\": [" + tiles +
                                                               "], \"split_depths\": [" + splits + "]}");
    const ShadowSetup setup = imported(inputs, file, {});
    ASSERT_EQ(setup.maps.size(), cascades.maps.size());
    EXPECT_EQ(setup.selection.rule, MapSelection::Rule::view_depth);
    EXPECT_EQ(setup.selection.split_depths, cascades.selection.split_depths);
    for (size_t k = 0; k < setup.maps.size(); ++k) {
        expect_same_matrix(setup.maps[k].world_to_uvz, cascades.maps[k].world_to_uvz, "cascade " + std::to_string(k));
        EXPECT_EQ(setup.maps[k].viewport, cascades.maps[k].viewport);
    }
    const MeasureContext context = prepare_measurement(box_on_plane(), 320, 180);
    const Measurement original = measure(context, method_or_throw("cascades"), defaults("cascades"), 1024, -1.0);
    EXPECT_NEAR(
        measure(context, method_or_throw("custom"), custom_settings_for(file, {}), 1024, -1.0).error.misclassified,
        original.error.misclassified, 1.0 / original.error.receiver_pixels);
}

// GLM's own projections, each under its API's conventions: the light box's near corner lands on
// (0, 0, 0), its far corner on (1, 1, 1), whatever the clip depth, the z direction or v.
TEST(MatrixImport, GlmsProjectionsLandOnTheUnitCube) {
    const glm::dmat4 light_from_world = glm::lookAt(glm::dvec3(1, 10, 2), glm::dvec3(0, 0, 0), glm::dvec3(0, 0, -1));
    const double l = -3, r = 5, b = -2, t = 4, n = 1, f = 20;
    const glm::dmat4 world_from_light = glm::inverse(light_from_world);
    const glm::dvec3 ws_near = transform_point(world_from_light, {l, b, -n}),
                     ws_far = transform_point(world_from_light, {r, t, -f});
    struct Case {
        glm::dmat4 clip_from_light;
        ClipConventions conventions;
        glm::dvec3 near_uvz, far_uvz;
    };
    for (const Case& c : {
             Case{glm::orthoRH_NO(l, r, b, t, n, f), {}, {0, 0, 0}, {1, 1, 1}},
             Case{glm::orthoRH_ZO(l, r, b, t, n, f), {.depth = ClipDepth::zero_to_one}, {0, 0, 0}, {1, 1, 1}},
             // reversed Z: the far plane given as near, so that z / w = 1 at the light's near plane
             Case{glm::orthoRH_ZO(l, r, b, t, f, n),
                  {.depth = ClipDepth::zero_to_one, .reversed_z = true},
                  {0, 0, 0},
                  {1, 1, 1}},
             Case{glm::orthoRH_NO(l, r, b, t, f, n), {.reversed_z = true}, {0, 0, 0}, {1, 1, 1}},
             // Direct3D reads v against y: the box's bottom edge is v = 1
             Case{glm::orthoRH_ZO(l, r, b, t, n, f),
                  {.depth = ClipDepth::zero_to_one, .v = TextureV::down},
                  {0, 1, 0},
                  {1, 0, 1}},
         }) {
        const glm::dmat4 world_to_uvz = uvz_from_clip(c.conventions) * c.clip_from_light * light_from_world;
        const glm::dvec3 near_uvz = transform_point(world_to_uvz, ws_near),
                         far_uvz = transform_point(world_to_uvz, ws_far);
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(near_uvz[i], c.near_uvz[i], 1e-12);
            EXPECT_NEAR(far_uvz[i], c.far_uvz[i], 1e-12);
        }
    }
    // A spot's perspective (Vulkan, [0, 1]): depth 0 on the near plane, 1 on the far, u, v across the cone.
    const glm::dmat4 world_to_uvz = uvz_from_clip({.depth = ClipDepth::zero_to_one}) *
                                    glm::perspectiveRH_ZO(glm::radians(90.0), 1.0, n, f) * light_from_world;
    const glm::dvec3 at_near = transform_point(world_to_uvz, transform_point(world_from_light, {n, n, -n}));
    const glm::dvec3 at_far = transform_point(world_to_uvz, transform_point(world_from_light, {-f, -f, -f}));
    EXPECT_NEAR(at_near.x, 1.0, 1e-12);
    EXPECT_NEAR(at_near.y, 1.0, 1e-12);
    EXPECT_NEAR(at_near.z, 0.0, 1e-12);
    EXPECT_NEAR(at_far.x, 0.0, 1e-12);
    EXPECT_NEAR(at_far.y, 0.0, 1e-12);
    EXPECT_NEAR(at_far.z, 1.0, 1e-12);
}

// The focused map squeezed to the middle half of its square: the ground beyond it is missed, named
// by its box (the 20 x 20 plane around the origin), and every point reported lies outside the map.
TEST(MatrixImport, ALightBoxTooSmallIsReportedWithTheReceiversItMisses) {
    const ShadowInputs inputs = gather_inputs(box_on_plane());
    const glm::dmat4 middle_half = from_rows({2, 0, 0, -0.5}, {0, 2, 0, -0.5}, {0, 0, 1, 0}, {0, 0, 0, 1});
    const glm::dmat4 small = middle_half * own_setup("focused", inputs).maps[0].world_to_uvz;
    const std::string file = written_file("small.glsl", opengl().written(engine_matrix(opengl(), small)));
    const ShadowSetup setup = imported(inputs, file, {});
    ASSERT_TRUE(has_note(setup.fallbacks, NoteKind::missed_receivers)) << describe(setup.fallbacks);
    EXPECT_NE(describe(setup.fallbacks).find("(-10, 0, -10)..(10, 0, 10)"), std::string::npos)
        << describe(setup.fallbacks);
    const MapCoverage coverage = map_coverage(inputs, setup);
    ASSERT_FALSE(coverage.missed_points.empty());
    for (const glm::dvec3& p : coverage.missed_points) {
        EXPECT_TRUE(inputs.frustum.contains(p, 1e-6));
        EXPECT_FALSE(in_unit_cube(world_to_uvz(setup.maps[0], p), 1e-9));
    }
    EXPECT_GT(coverage.missed_points.size(), 0u);
    EXPECT_LT(coverage.missed_points.size(), coverage.receiver_points.size()) << "the middle of the view is held";
}

// A map twice as wide as the focused one spends three quarters of its texels beyond the view.
TEST(MatrixImport, TexelsOutsideTheViewAreCounted) {
    const ShadowInputs inputs = gather_inputs(box_on_plane());
    const ShadowSetup focused = own_setup("focused", inputs);
    const glm::dmat4 twice_as_wide = from_rows({0.5, 0, 0, 0.25}, {0, 0.5, 0, 0.25}, {0, 0, 1, 0}, {0, 0, 0, 1});
    ShadowSetup wide = focused;
    wide.maps[0].world_to_uvz = twice_as_wide * focused.maps[0].world_to_uvz;
    const double own = map_coverage(inputs, focused).texels_outside_view;
    EXPECT_GE(own, 0.0);
    EXPECT_NEAR(map_coverage(inputs, wide).texels_outside_view, 1.0 - (1.0 - own) / 4.0, 1e-9);
    const std::vector<Note> notes = coverage_notes(map_coverage(inputs, wide));
    EXPECT_EQ(has_note(notes, NoteKind::texels_outside_view), 1.0 - (1.0 - own) / 4.0 > kWastedShareNoted);
}

TEST(MatrixImport, MalformedTextIsRefusedWithTheReason) {
    std::string fifteen = "1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0";
    const std::string identity = fifteen + ", 1";
    for (const auto& [text, reason] : std::vector<std::pair<std::string, std::string>>{
             {mat4_of(fifteen), "engine.txt: matrix 0 (line 1): expected 16 numbers, got 15"},
             {mat4_of("1, 0, 0, 0, 0, 1, x, 0, 0, 0, 1, 0, 0, 0, 0, 1"), "matrix 0 (line 1): 'x' is not a number"},
             {mat4_of("nan, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1"), "'nan' is not a finite number"},
             {mat4_of("1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1e999, 1"), "'1e999' is not a finite number"},
             {mat4_of("1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1"), "matrix 0 (line 1): singular matrix"},
             {mat4_of(identity) + "\n" + mat4_of(fifteen), "matrix 1 (line 2): expected 16 numbers, got 15"},
             {mat4_of(identity) + "\n" + mat4_of(identity), "2 matrices: give each its tile"},
             {"static const float4x4 m = {" + fifteen + "};", "matrix 0 (line 1): expected 16 numbers, got 15"},
             {"shadow matrix: 1 0 0 0", "no matrix found"},
             {"{\"matrices\": [[" + identity + "]]}", "matrices[0]: 16 numbers in a row: name their storage"},
             {"{\"matrices\": [[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0]]]}",
              "matrices[0][3]: expected 4 numbers, got 3"},
             {"{\"matrices\": [[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, NaN]]]}", "malformed JSON"},
             {"{\"matrices\": [[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, \"1\"]]]}",
              "matrices[0][3]: expected finite numbers"},
             {"{\"matrices\": [], \"lens\": {}}", "lens: unknown key"},
             {"{\"matrices\": []}", "matrices: expected an array of one or more matrices"},
             {"{\"matrices\": [[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]], \"tiles\": [[0, 0, 2, 1]]}",
              "tiles[0]: expected [u0, v0, u1, v1]"},
             {"{\"matrices\": [[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]], \"split_depths\": [5, 1]}",
              "split_depths: expected 2 increasing view depths"},
         }) {
        const std::string message = refusal(text);
        EXPECT_NE(message.find(reason), std::string::npos) << text << "\n  gave: " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
    }
    EXPECT_EQ(refusal("{\"matrices\": [[" + identity + "]]}", MatrixStorage::row_major), "(accepted)")
        << "named storage reads 16 numbers in a row";
    EXPECT_EQ(refusal("float4x4 m = float4x4(float4(1, 0, 0, 0), float4(0, 1, 0, 0), float4(0, 0, 1, 0), "
                      "float4(0, 0, 0, 1.f));"),
              "(accepted)")
        << "HLSL's vector constructors are read through";
    try {
        read_engine_matrices("/nonexistent/engine.glsl", MatrixStorage::automatic);
        ADD_FAILURE() << "a missing file is refused";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()), "/nonexistent/engine.glsl: cannot open file");
    }
}

// Storage named against the text's own order transposes: row_major GLSL is the transpose of auto.
TEST(MatrixImport, NamedStorageOverridesTheLanguagesOrder) {
    const std::string text = mat4_of("1, 2, 3, 4, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1");
    const glm::dmat4 by_columns = parse_engine_matrices(text, MatrixStorage::automatic, "").clip_from_world[0];
    const glm::dmat4 by_rows = parse_engine_matrices(text, MatrixStorage::row_major, "").clip_from_world[0];
    EXPECT_EQ(by_columns[0], glm::dvec4(1, 2, 3, 4));  // GLSL's first four numbers: column 0
    EXPECT_EQ(by_rows, glm::transpose(by_columns));
}

TEST(MatrixImport, WithNoFileTheFocusedMapIsANamedFallback) {
    const ShadowInputs inputs = gather_inputs(box_on_plane());
    const ShadowSetup setup = own_setup("custom", inputs);
    EXPECT_TRUE(has_note(setup.fallbacks, NoteKind::no_matrices));
    expect_same_matrix(setup.maps[0].world_to_uvz, own_setup("focused", inputs).maps[0].world_to_uvz, "focused");
}
