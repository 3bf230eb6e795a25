// Issue 10's promise: a map method registered by a test binary (not shipped) goes through inspect,
// measure, render, every view and the GPU pass with no other edit; and so does a setup of two maps
// in an atlas, each tile rasterized, looked up and drawn.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <nlohmann/json.hpp>

#include "inspect_command.hpp"
#include "measure_command.hpp"
#include "methods/uniform.hpp"
#include "render_command.hpp"
#include "scene/scene_loader.hpp"
#include "view_test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kWidth = 480, kHeight = 270;

// Any map will do, the plumbing is under test: the uniform map, with a step of its own.
ShadowSetup throwaway_maps(const ShadowInputs& inputs, const Settings& settings, Trace* trace) {
    ShadowSetup setup = compute_uniform(inputs, settings, trace);
    record(trace, [&](Trace& t) {
        t.add("throwaway", "A test's own step", "the uniform map, unchanged", Space::unit)
            .value("maps", double(setup.maps.size()));
    });
    return setup;
}

// Two tiles of a 2x2 atlas, lower left and upper right: the uniform map twice, chosen by view depth,
// split at the camera's target.
ShadowSetup two_tiles(const ShadowInputs& inputs, const Settings& settings, Trace* trace) {
    const ShadowSetup uniform = compute_uniform(inputs, settings, trace);
    ShadowSetup setup{.fallbacks = uniform.fallbacks};
    for (const glm::dvec4& tile : {glm::dvec4(0.0, 0.0, 0.5, 0.5), glm::dvec4(0.5, 0.5, 1.0, 1.0)}) {
        ShadowMap map = uniform.maps.at(0);
        map.viewport = tile;
        setup.maps.push_back(map);
    }
    const Camera& camera = inputs.camera;
    setup.selection = {.rule = MapSelection::Rule::view_depth,
                       .eye = camera.position,
                       .view_axis = camera.view_direction(),
                       .split_depths = {0.0, glm::length(camera.target - camera.position), camera.far}};
    return setup;
}

class Extension : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        for (auto [name, compute] : {std::pair<const char*, ComputeMaps>{"throwaway", throwaway_maps},
                                     std::pair<const char*, ComputeMaps>{"two_tiles", two_tiles}})
            if (!find_method(name))
                register_method({.name = name, .title = name, .description = "a test's own", .compute_maps = compute});
    }

    static std::string scene_file() { return std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/box_on_plane.json"; }

    static Scene scene() {
        Scene s = load_scene(scene_file());
        s.camera.aspect = static_cast<double>(kWidth) / kHeight;
        return s;
    }
};

nlohmann::json measured(const std::string& scene, const std::string& method, int resolution) {
    return nlohmann::json::parse(printed([&] {
        run_measure({.scene_file = scene,
                     .method = method,
                     .resolution = resolution,
                     .width = 320,
                     .height = 180,
                     .json = true});
    }));
}

// Grey, map-drawn pixels (not white: empty texels; not the caption's rows) per quadrant of the
// Shadow map view's image: lower left, lower right, upper left, upper right of the texture.
std::array<size_t, 4> drawn_per_quadrant(const RgbImage& image) {
    std::array<size_t, 4> counts{};
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            if (y > image.height - 40) continue;  // the caption
            const unsigned char* c = image.at(x, y);
            if (c[0] != c[1] || c[1] != c[2] || c[0] >= 250) continue;
            const bool right = x >= image.width / 2, upper = y < image.height / 2;  // row 0 is the top
            ++counts[(upper ? 2 : 0) + (right ? 1 : 0)];
        }
    return counts;
}

}  // namespace

TEST_F(Extension, AThrowAwayMethodGoesThroughInspectMeasureRenderAndEveryView) {
    const nlohmann::json inspected = nlohmann::json::parse(
        printed([&] { run_inspect({.scene_file = scene_file(), .method = "throwaway", .json = true}); }));
    EXPECT_EQ(inspected["method"], "throwaway");
    EXPECT_EQ(inspected["steps"].back()["id"], "throwaway");
    EXPECT_EQ(inspected["maps"].size(), 1u);

    // The same map as the uniform method's: the same measure, to the last digit.
    const nlohmann::json mine = measured(scene_file(), "throwaway", 512),
                         uniform = measured(scene_file(), "uniform", 512);
    EXPECT_EQ(mine["method"], "throwaway");
    EXPECT_GT(mine["receiver_pixels"].get<int>(), 1000);
    EXPECT_EQ(mine["misclassified"], uniform["misclassified"]);
    EXPECT_EQ(mine["m"], uniform["m"]);

    for (const View& view : all_views()) {
        const std::string out = ::testing::TempDir() + "throwaway_" + view.name + ".png";
        std::filesystem::remove(out);
        run_render({.scene_file = scene_file(),
                    .method = "throwaway",
                    .view = view.name,
                    .width = 320,
                    .height = 180,
                    .resolution = 512,
                    .out = out});
        EXPECT_TRUE(std::filesystem::exists(out)) << view.name;
    }

    const Agreement gpu = gpu_against_cpu_lookup(inspect(scene(), "throwaway", 1024), kWidth, kHeight);
    ASSERT_GT(gpu.compared, kWidth * kHeight / 4u);
    EXPECT_GE(gpu.share(), 0.995) << gpu.compared - gpu.agreed << " of " << gpu.compared << " pixels differ";
}

TEST_F(Extension, TwoMapsInAnAtlasAreRasterizedLookedUpAndDrawn) {
    const Scene s = scene();
    // Each tile of the 2048² texture holds what the uniform map alone draws at 1024².
    const Inspection tiles = inspect(s, "two_tiles", 2048), whole = inspect(s, "uniform", 1024);
    size_t differ = 0, drawn = 0;
    for (int y = 0; y < 1024; ++y)
        for (int x = 0; x < 1024; ++x) {
            differ += tiles.depth().at(x, y) != whole.depth().at(x, y);
            differ += tiles.depth().at(x + 1024, y + 1024) != whole.depth().at(x, y);
            differ += tiles.depth().at(x + 1024, y) != 1.0f || tiles.depth().at(x, y + 1024) != 1.0f;  // unused tiles
            drawn += whole.depth().at(x, y) < 1.0f;
        }
    EXPECT_EQ(differ, 0u);
    EXPECT_GT(drawn, 1000u);

    // Both maps serve pixels, and the verdicts are the single map's, pixel for pixel.
    const ReferenceImage& ref = tiles.reference(kWidth, kHeight);
    std::array<size_t, 2> served{};
    for (size_t i = 0; i < ref.visible.size(); ++i)
        if (ref.visible[i])
            if (const int map = select_map(tiles.setup, ref.position[i]); map >= 0) ++served[map];
    EXPECT_GT(served[0], 1000u);
    EXPECT_GT(served[1], 1000u);
    const ShadowError& a = tiles.error(kWidth, kHeight);
    const ShadowError& b = whole.error(kWidth, kHeight);
    EXPECT_EQ(a.verdicts, b.verdicts);
    EXPECT_EQ(a.m.max, b.m.max);

    // The Shadow map view draws both tiles and leaves the other two empty.
    const std::array<size_t, 4> quadrants =
        drawn_per_quadrant(render_view(tiles, view_or_throw("shadowmap"), {}, 512, 512));
    EXPECT_GT(quadrants[0], 200u);
    EXPECT_NEAR(double(quadrants[3]), double(quadrants[0]), 0.05 * quadrants[0]) << "the same picture in both tiles";
    EXPECT_EQ(quadrants[1], 0u);
    EXPECT_EQ(quadrants[2], 0u);

    // The GPU pass renders both tiles and looks each pixel up in its own.
    const Agreement gpu = gpu_against_cpu_lookup(tiles, kWidth, kHeight);
    ASSERT_GT(gpu.compared, kWidth * kHeight / 4u);
    EXPECT_GE(gpu.share(), 0.995) << gpu.compared - gpu.agreed << " of " << gpu.compared << " pixels differ";

    const nlohmann::json inspected = nlohmann::json::parse(
        printed([&] { run_inspect({.scene_file = scene_file(), .method = "two_tiles", .json = true}); }));
    ASSERT_EQ(inspected["maps"].size(), 2u);
    EXPECT_EQ(inspected["maps"][1]["viewport"], nlohmann::json({0.5, 0.5, 1.0, 1.0}));
    EXPECT_EQ(inspected["selection"]["rule"], "by view depth");
}
