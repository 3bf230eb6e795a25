// The command line as a user runs it: exit codes, one-line errors naming file and field, and the
// JSON object of `shadowlab inspect --json`.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include "cli_support.hpp"
#include "gltf_support.hpp"
#include "test_support.hpp"

using shadowlab::testing::CliResult;
using shadowlab::testing::run_cli;
using shadowlab::testing::slurp;
using shadowlab::testing::source_path;

namespace {

// Each entry of a "fallbacks" or "limits" array names a kind of note of that category.
bool notes_of_category(const nlohmann::json& notes, shadowlab::NoteCategory category) {
    for (const auto& note : notes) {
        bool known = false;
        for (const shadowlab::NoteInfo& info : shadowlab::all_note_kinds())
            known |=
                note["kind"] == info.name && info.category == category && !note["message"].get<std::string>().empty();
        if (!known) return false;
    }
    return true;
}

std::map<std::string, std::string> expected_bad_scenes() {
    std::map<std::string, std::string> expected;
    std::istringstream lines(slurp(source_path("tests/data/bad/EXPECTED.tsv")));
    for (std::string line; std::getline(lines, line);) {
        const auto tab = line.find('\t');
        if (tab != std::string::npos && line[0] != '#') expected[line.substr(0, tab)] = line.substr(tab + 1);
    }
    return expected;
}

// Each face's vertices lie on one plane that has every vertex on its inner side, and every
// directed edge has its twin: the polyhedron is closed and convex.
void expect_closed_convex(const nlohmann::json& poly) {
    std::vector<glm::dvec3> v;
    for (const auto& p : poly["vertices"]) v.push_back({p[0], p[1], p[2]});
    std::map<std::pair<int, int>, int> edges;
    double size = 0;
    for (const auto& p : v) size = std::max(size, glm::length(p));
    for (const auto& face : poly["faces"]) {
        std::vector<int> loop = face.get<std::vector<int>>();
        ASSERT_GE(loop.size(), 3u);
        glm::dvec3 normal{0.0};  // Newell's method
        for (size_t i = 0; i < loop.size(); ++i) {
            const glm::dvec3 &a = v[loop[i]], &b = v[loop[(i + 1) % loop.size()]];
            normal += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
            ++edges[{loop[i], loop[(i + 1) % loop.size()]}];
        }
        normal = glm::normalize(normal);
        for (const auto& p : v) EXPECT_LE(glm::dot(normal, p - v[loop[0]]), 1e-7 * size);
    }
    for (const auto& [edge, count] : edges) {
        EXPECT_EQ(count, 1);
        EXPECT_EQ(edges.count({edge.second, edge.first}), 1u);
    }
}

}  // namespace

TEST(Cli, EachBadSceneGivesItsMessageAndANonZeroExit) {
    const auto expected = expected_bad_scenes();
    ASSERT_GE(expected.size(), 10u);
    for (const auto& [file, message] : expected) {
        const CliResult r = run_cli("inspect " + source_path("tests/data/bad/" + file));
        EXPECT_NE(r.exit_code, 0) << file;
        EXPECT_NE(r.err.find(file), std::string::npos) << file << ": " << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << file << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
        EXPECT_TRUE(r.out.empty()) << file;
    }
}

TEST(Cli, UnknownMethodAndBadSettingAreRejected) {
    const std::string scene = source_path("data/scenes/default.json");
    CliResult r = run_cli("inspect " + scene + " --method nonesuch");
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("unknown method 'nonesuch'"), std::string::npos) << r.err;
    r = run_cli("inspect " + scene + " --method focused --set kernel=fast");
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("kernel"), std::string::npos) << r.err;
    r = run_cli("inspect " + scene + " --set nokey");
    EXPECT_NE(r.exit_code, 0);
}

TEST(Cli, FocusedJsonHasTheDocumentedShapeAndAClosedConvexBody) {
    const CliResult r = run_cli("inspect " + source_path("data/scenes/default.json") + " --method focused --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["method"], "focused");
    EXPECT_EQ(j["settings"]["kernel"], "float");
    EXPECT_TRUE(j["fallback"].is_null());
    EXPECT_GT(j["inputs"]["receivers"].size(), 8u);
    EXPECT_GT(j["inputs"]["casters"].size(), 8u);
    ASSERT_EQ(j["maps"].size(), 1u);
    EXPECT_EQ(j["maps"][0]["world_to_uvz"].size(), 4u);
    EXPECT_EQ(j["maps"][0]["viewport"], nlohmann::json({0.0, 0.0, 1.0, 1.0}));
    EXPECT_GT(j["maps"][0]["z_bias_scale"].get<double>(), 0.0);
    const nlohmann::json* body = nullptr;
    for (const auto& step : j["steps"])
        if (step["id"] == "body")
            for (const auto& g : step["geometry"])
                if (g["kind"] == "polyhedron") body = &g;
    ASSERT_NE(body, nullptr);
    expect_closed_convex(*body);
}

TEST(Cli, EveryKernelGivesTheSameBodyVolume) {
    std::vector<double> volumes;
    for (const char* kernel : {"float", "epick", "epeck"}) {
        const CliResult r = run_cli("inspect " + source_path("data/scenes/default.json") +
                                    " --method focused --json --set kernel=" + kernel);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const nlohmann::json j = nlohmann::json::parse(r.out);
        for (const auto& step : j["steps"])
            if (step["id"] == "body") volumes.push_back(step["values"]["volume"]);
    }
    ASSERT_EQ(volumes.size(), 3u);
    EXPECT_NEAR(volumes[0], volumes[2], 1e-4 * volumes[2]);
    EXPECT_NEAR(volumes[1], volumes[2], 1e-4 * volumes[2]);
}

TEST(Cli, TextInspectionNamesTheStepsAndTheFallback) {
    const CliResult r = run_cli("inspect " + source_path("data/scenes/default.json") + " --method uniform");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("fallback: none"), std::string::npos);
    EXPECT_NE(r.out.find("Scene bounds"), std::string::npos);
    EXPECT_NE(r.out.find("world_to_uvz"), std::string::npos);
}

TEST(Cli, EveryMethodOnEveryHardCaseGivesAMapOrANamedFallback) {
    for (const char* scene : {"default", "light_parallel_behind", "light_parallel_front", "casters_behind",
                              "light_overhead", "far_near_1e5"})
        for (const shadowlab::Method* m : shadowlab::testing::map_methods()) {
            const std::string& method = m->name;
            const CliResult r = run_cli("inspect " + source_path(std::string("data/scenes/") + scene + ".json") +
                                        " --json --method " + method);
            ASSERT_EQ(r.exit_code, 0) << scene << " " << method << ": " << r.err;
            const nlohmann::json j = nlohmann::json::parse(r.out);
            EXPECT_GE(j["steps"].size(), 5u) << scene << " " << method;
            EXPECT_EQ(j["fallback"].is_null(), j["fallbacks"].empty()) << j["fallback"];
            EXPECT_TRUE(notes_of_category(j["fallbacks"], shadowlab::NoteCategory::fallback)) << j["fallbacks"];
            for (const auto& row : j["maps"].at(0)["world_to_uvz"])
                for (const auto& x : row) EXPECT_TRUE(x.is_number()) << scene << " " << method << ": not finite";
        }
}

TEST(Cli, MeasurePrintsTheDocumentedObject) {
    const CliResult r = run_cli("measure " + source_path("data/scenes/default.json") +
                                " --method lispsm --resolution 1024 --size 320x180 --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["method"], "lispsm");
    EXPECT_EQ(j["resolution"], 1024);
    EXPECT_EQ(j["texels_used"], 1024.0 * 1024.0) << "one map fills the texture";
    for (const char* share : {"misclassified", "false_shadow", "false_light"}) {
        EXPECT_GE(j[share].get<double>(), 0.0) << share;
        EXPECT_LE(j[share].get<double>(), 1.0) << share;
    }
    EXPECT_NEAR(j["misclassified"].get<double>(), j["false_shadow"].get<double>() + j["false_light"].get<double>(),
                1e-12);
    EXPECT_GT(j["m"]["max"].get<double>(), j["m"]["mean"].get<double>());
    EXPECT_GT(j["setup_ms"].get<double>(), 0.0);
    EXPECT_GT(j["raster_ms"].get<double>(), 0.0);
    EXPECT_TRUE(j["fallback"].is_null());
    EXPECT_NE(r.err.find("measure: exact reference"), std::string::npos) << "progress on stderr";
    // Lloyd's two factors beside m; their product is m pixel by pixel, so the perspective part,
    // which a parameterization controls, never exceeds m.
    for (const char* factor : {"m_perspective", "m_projection"})
        for (const char* stat : {"max", "mean", "p95"}) EXPECT_GT(j[factor][stat].get<double>(), 0.0) << factor << stat;
    EXPECT_LE(j["m_perspective"]["max"].get<double>(), j["m"]["max"].get<double>());
    EXPECT_EQ(j["image"], nlohmann::json({320, 180}));
}

// One aspect rule: an image asked in another shape keeps the camera's aspect, so a square camera
// measured at 1280x720 and at 720x720 is the same 720x720 image with the same m per pixel.
TEST(Cli, MeasureKeepsTheCamerasAspect) {
    const std::string square = ::testing::TempDir() + "square_camera.json";
    {
        nlohmann::json scene = nlohmann::json::parse(slurp(source_path("data/scenes/box_on_plane.json")));
        scene["camera"]["aspect"] = 1.0;
        std::ofstream(square) << scene.dump();
    }
    auto measured = [&](const std::string& size) {
        const CliResult r =
            run_cli("measure " + square + " --method focused --resolution 512 --size " + size + " --json");
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return nlohmann::json::parse(r.out);
    };
    const nlohmann::json wide = measured("1280x720"), square_image = measured("720x720");
    EXPECT_EQ(wide["image"], nlohmann::json({720, 720}));
    EXPECT_EQ(wide["m"], square_image["m"]);
    EXPECT_EQ(wide["misclassified"], square_image["misclassified"]);
}

TEST(Cli, MeasureRejectsBadArguments) {
    const std::string scene = source_path("data/scenes/default.json");
    EXPECT_NE(run_cli("measure " + scene + " --resolution 0").exit_code, 0);
    EXPECT_NE(run_cli("measure " + scene + " --size 12by7").exit_code, 0);
    const CliResult r = run_cli("measure " + source_path("tests/data/bad/near_ge_far.json"));
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("camera.far"), std::string::npos) << r.err;
}

namespace {

std::vector<std::string> lines_of(const std::string& file) {
    std::istringstream in(slurp(file));
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

bool is_png(const std::string& file) { return slurp(file).rfind("\x89PNG", 0) == 0; }

}  // namespace

TEST(Cli, BenchWritesItsCsvAndPlot) {
    const std::string out = ::testing::TempDir() + "shadowlab_bench";
    std::filesystem::remove_all(out);
    const CliResult r = run_cli("bench " + source_path("data/scenes/box_on_plane.json") +
                                " --methods uniform,focused --resolutions 16,512 --size 160x90 --out " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<std::string> csv = lines_of(out + "/bench.csv");
    ASSERT_EQ(csv.size(), 5u);  // header + 2 methods x 2 resolutions
    EXPECT_EQ(csv[0].rfind("scene,method,resolution,misclassified", 0), 0u);
    EXPECT_NE(csv[1].find(",uniform,16,"), std::string::npos);
    EXPECT_NE(csv[4].find(",focused,512,"), std::string::npos);
    EXPECT_TRUE(is_png(out + "/bench.png"));
    EXPECT_NE(r.err.find("bench: [4/4]"), std::string::npos) << "progress: " << r.err;
}

TEST(Cli, SweepMarksXpsmsMinersLampAsTheLightTurnsParallel) {
    const std::string out = ::testing::TempDir() + "shadowlab_sweep";
    std::filesystem::remove_all(out);
    const CliResult r = run_cli("sweep " + source_path("data/scenes/box_on_plane.json") +
                                " --methods focused,xpsm --resolution 256 --size 96x54 --out " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<std::string> csv = lines_of(out + "/sweep.csv");
    ASSERT_EQ(csv.size(), 1u + (11 + 7) * 2);
    int lamps = 0;
    for (const std::string& line : csv)
        if (line.rfind("angle_deg,", 0) == 0 && line.find(",xpsm,") != std::string::npos)
            lamps += line.find("miner's lamp") != std::string::npos;
    EXPECT_GE(lamps, 5) << "γ of 3° and less is XPSM's miner's lamp";
    EXPECT_TRUE(is_png(out + "/sweep_angle.png"));
    EXPECT_TRUE(is_png(out + "/sweep_far_near.png"));
}

TEST(Cli, SweepBiasWritesEachMethodsCurveItsBestAndAPlot) {
    const std::string out = ::testing::TempDir() + "shadowlab_sweep_bias";
    std::filesystem::remove_all(out);
    const CliResult r = run_cli("sweep " + source_path("data/scenes/box_on_plane.json") +
                                " --bias --bias-setting bias_normal --methods focused,volumes,lispsm --resolution 256"
                                " --size 96x54 --out " +
                                out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("volumes skipped"), std::string::npos) << "a technique has no bias: " << r.err;
    const std::vector<std::string> csv = lines_of(out + "/sweep_bias.csv");
    ASSERT_GT(csv.size(), 1u);
    EXPECT_EQ(csv[0], "method,setting,value,false_shadow,false_light,misclassified,best,fallback");
    std::map<std::string, int> rows, best;
    for (size_t i = 1; i < csv.size(); ++i) {
        const std::string method = csv[i].substr(0, csv[i].find(','));
        EXPECT_EQ(csv[i].find(method + ",bias_normal,"), 0u) << csv[i];
        ++rows[method];
        best[method] += csv[i].find(",1,\"") != std::string::npos;
    }
    EXPECT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows["focused"], rows["lispsm"]) << "one ladder for every method";
    EXPECT_EQ(best["focused"], 1) << "one best point per method";
    EXPECT_EQ(best["lispsm"], 1);
    EXPECT_NE(r.out.find("focused: best bias_normal"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("lispsm: best bias_normal"), std::string::npos) << r.out;
    EXPECT_TRUE(is_png(out + "/sweep_bias.png"));
    EXPECT_FALSE(std::filesystem::exists(out + "/sweep.csv")) << "--bias replaces the light and far/near sweeps";
}

TEST(Cli, SweepBiasSettingNeedsBias) {
    const CliResult r = run_cli("sweep " + source_path("data/scenes/box_on_plane.json") +
                                " --bias-setting bias_normal --out " + ::testing::TempDir() + "shadowlab_unused");
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("--bias"), std::string::npos) << r.err;
}

TEST(Cli, InspectVolumesListsSilhouetteEdgesAndQuadsAtInfinity) {
    const CliResult r = run_cli("inspect " + source_path("data/scenes/volumes.json") + " --method volumes --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["method"], "volumes");
    EXPECT_EQ(j["settings"]["count"], "zfail");
    EXPECT_TRUE(j["limits"].empty()) << j["limits"];
    std::map<std::string, nlohmann::json> geometry;
    for (const auto& step : j["steps"])
        for (const auto& g : step["geometry"])
            geometry[step["id"].get<std::string>() + "/" + g["kind"].get<std::string>()] = g;
    ASSERT_TRUE(geometry.count("volumes.silhouette/segments"));
    ASSERT_TRUE(geometry.count("volumes.extrusion/polygons"));
    const auto& segments = geometry["volumes.silhouette/segments"]["segments"];
    const auto& quads = geometry["volumes.extrusion/polygons"];
    EXPECT_GT(segments.size(), 20u);
    EXPECT_EQ(quads["polygons"].size(), segments.size());
    for (const auto& polygon : quads["polygons"]) {
        ASSERT_EQ(polygon.size(), 4u);
        EXPECT_EQ(quads["vertices"][polygon[1].get<int>()][3], 1.0);  // on the caster
        EXPECT_EQ(quads["vertices"][polygon[2].get<int>()][3], 0.0);  // at infinity
    }
}

TEST(Cli, MeasureVolumesPrintsTheMapKeysAndItsOwn) {
    const CliResult r = run_cli("measure " + source_path("data/scenes/volumes_eye_in_shadow.json") +
                                " --method volumes --set count=zpass --size 160x90 --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    for (const char* key : {"method", "resolution", "misclassified", "false_shadow", "false_light", "m", "setup_ms",
                            "raster_ms", "fallback", "limits", "polygons", "fill_mean", "fill_max"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_EQ(j["resolution"], 0);
    EXPECT_EQ(j["m"]["max"], 0.0);
    EXPECT_GT(j["polygons"].get<int>(), 0);
    EXPECT_GE(j["fill_max"].get<double>(), j["fill_mean"].get<double>());
    EXPECT_TRUE(j["fallback"].is_null()) << "a technique's limits are not fallbacks: " << j["fallback"];
    ASSERT_TRUE(notes_of_category(j["limits"], shadowlab::NoteCategory::limit)) << j["limits"];
    ASSERT_EQ(j["limits"].size(), 1u) << j["limits"];
    EXPECT_EQ(j["limits"][0]["kind"], shadowlab::to_string(shadowlab::NoteKind::eye_in_volume));
    EXPECT_GT(j["misclassified"].get<double>(), 0.3) << "z-pass from inside a volume";
}

TEST(Cli, BenchPutsVolumesAndMapsInOneTable) {
    const std::string out = ::testing::TempDir() + "shadowlab_bench_volumes";
    std::filesystem::remove_all(out);
    const CliResult r = run_cli("bench " + source_path("data/scenes/volumes.json") +
                                " --methods focused,volumes,planar --resolutions 256,1024 --size 160x90 --out " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<std::string> csv = lines_of(out + "/bench.csv");
    ASSERT_EQ(csv.size(), 5u);  // header + focused at 2 resolutions + volumes + planar once each
    EXPECT_NE(csv[0].find(",polygons,fill_mean,fill_max"), std::string::npos) << csv[0];
    EXPECT_NE(csv[3].find(",volumes,0,"), std::string::npos) << csv[3];
    EXPECT_NE(csv[4].find(",planar,0,"), std::string::npos) << csv[4];
    EXPECT_TRUE(csv[1].size() > 3 && csv[1].substr(csv[1].size() - 3) == ",,,") << "a map has no polygons: " << csv[1];
}

// A glTF scene opens in the commands as it is: with its own camera (its aspect, 1.5, shapes the
// measured image), what it lacks named on stderr, a broken file refused by name.
TEST(Cli, InspectAndMeasureOpenAGltfSceneWithItsCamera) {
    using shadowlab::testing::two_camera_scene;
    using shadowlab::testing::write_test_file;
    const std::string file = write_test_file("cli_two_cameras.gltf", two_camera_scene().dump());
    const CliResult inspect = run_cli("inspect " + file + " --json");
    ASSERT_EQ(inspect.exit_code, 0) << inspect.err;
    EXPECT_FALSE(nlohmann::json::parse(inspect.out)["inputs"]["casters"].empty());
    const CliResult measure = run_cli("measure " + file + " --resolution 256 --size 300x300 --json");
    ASSERT_EQ(measure.exit_code, 0) << measure.err;
    EXPECT_EQ(nlohmann::json::parse(measure.out)["image"], nlohmann::json({300, 200}));

    nlohmann::json unlit = two_camera_scene();
    unlit.erase("extensions");
    for (nlohmann::json& node : unlit["nodes"]) node.erase("extensions");
    const std::string unlit_file = write_test_file("cli_unlit.gltf", unlit.dump());
    const CliResult defaulted = run_cli("inspect " + unlit_file);
    EXPECT_EQ(defaulted.exit_code, 0) << defaulted.err;
    EXPECT_NE(defaulted.err.find(unlit_file + ": no KHR_lights_punctual light"), std::string::npos) << defaulted.err;

    const CliResult broken = run_cli("inspect " + write_test_file("cli_broken.gltf", R"({"asset":)"));
    EXPECT_NE(broken.exit_code, 0);
    EXPECT_NE(broken.err.find("cli_broken.gltf: malformed JSON"), std::string::npos) << broken.err;
}

// An engine's matrix from a file: the focused map as `inspect --json` prints it (rows of world_to_uvz),
// written as an OpenGL engine's GLSL (clip x, y, z = 2 (u, v, d) - w, by columns), measures as the
// focused map does; 15 numbers are refused on one line naming the file and the matrix.
TEST(Cli, MeasureReadsAnEnginesMatricesFromAFile) {
    const std::string scene = source_path("data/scenes/box_on_plane.json");
    const CliResult inspected = run_cli("inspect " + scene + " --method focused --json");
    ASSERT_EQ(inspected.exit_code, 0) << inspected.err;
    const nlohmann::json uvz = nlohmann::json::parse(inspected.out)["maps"][0]["world_to_uvz"];
    std::string columns;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            const double w = uvz[3][c], clip = r == 3 ? w : 2.0 * uvz[r][c].get<double>() - w;
            char number[32];
            std::snprintf(number, sizeof number, "%.17g", clip);
            columns += (columns.empty() ? "" : ", ") + std::string(number);
        }
    const std::string file = ::testing::TempDir() + "cli_light_view_projection.glsl";
    std::ofstream(file) << "const mat4 lightViewProjection = mat4(" << columns << ");\n";
    auto measured = [&](const std::string& method) {
        const CliResult r =
            run_cli("measure " + scene + " --method " + method + " --resolution 512 --size 320x180 --json");
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return nlohmann::json::parse(r.out);
    };
    const nlohmann::json focused = measured("focused"), custom = measured("custom --set matrices=" + file);
    EXPECT_EQ(custom["method"], "custom");
    EXPECT_NEAR(custom["misclassified"].get<double>(), focused["misclassified"].get<double>(),
                1.0 / focused["receiver_pixels"].get<double>());
    for (const auto& note : custom["fallbacks"])
        EXPECT_NE(note["kind"], shadowlab::to_string(shadowlab::NoteKind::missed_receivers)) << custom["fallbacks"];

    const std::string bad = ::testing::TempDir() + "cli_fifteen_numbers.glsl";
    std::ofstream(bad) << "mat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0)\n";
    const CliResult r = run_cli("inspect " + scene + " --method custom --set matrices=" + bad);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find(bad + ": matrix 0 (line 1): expected 16 numbers, got 15"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
}

// --camera-index and --light-index pick another of a glTF file's cameras and lights, by number.
TEST(Cli, CameraAndLightIndexPickAmongAGltfFilesOwn) {
    const std::string file =
        shadowlab::testing::write_test_file("cli_choice.gltf", shadowlab::testing::two_camera_scene().dump());
    const CliResult side =
        run_cli("measure " + file + " --camera-index 1 --light-index 1 --resolution 256 --size 300x300 --json");
    ASSERT_EQ(side.exit_code, 0) << side.err;
    // The side camera has no aspectRatio: 16:9, said on stderr.
    EXPECT_EQ(nlohmann::json::parse(side.out)["image"], nlohmann::json({300, std::lround(300 * 9.0 / 16.0)}));
    EXPECT_NE(side.err.find("cameras[1].perspective has no aspectRatio"), std::string::npos) << side.err;
    const CliResult beyond = run_cli("inspect " + file + " --camera-index 2");
    EXPECT_NE(beyond.exit_code, 0);
    EXPECT_NE(beyond.err.find("camera 2 asked for, but the file holds 2 cameras (0 … 1)"), std::string::npos)
        << beyond.err;
}
