// Issue 25's promise for filters: a filter registered by a test binary (not shipped) goes through
// measure, render, the GPU pass and the window's Controls panel with no other edit. The throw-away
// filter lights every receiver, so that each path shows it ran: no pixel left in shadow.
#include <gtest/gtest.h>

#include <QApplication>
#include <QComboBox>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <nlohmann/json.hpp>

#include "gui/controls_panel.hpp"
#include "lookup/shadow_reader.hpp"
#include "measure_command.hpp"
#include "registry/filter_registry.hpp"
#include "render_command.hpp"
#include "scene/scene_loader.hpp"
#include "view_test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kWidth = 480, kHeight = 270;

std::vector<KernelTap> no_taps(const ShadowFilter&) { return {}; }
int no_reads(const ShadowFilter&) { return 0; }
double lit(const ShadowReader&, const MapReceiver&, const Receiver&, LookupCount*) { return 1.0; }

std::string scene_file() { return std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/box_on_plane.json"; }

class FilterExtension : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        static int argc = 1;
        static char name[] = "shadowlab_filter_extension_tests";
        static char* argv[] = {name, nullptr};
        if (!QApplication::instance()) new QApplication(argc, argv);  // for the whole run: Qt outlives the tests
        if (!find_filter("lit_everywhere"))
            register_filter({.name = "lit_everywhere",
                             .description = "a test's own: every receiver lit",
                             .taps = no_taps,
                             .texel_reads = no_reads,
                             .visibility = lit,
                             .glsl = "float shadowFilter_lit_everywhere(int i, ShadowMapReceiver m, float rotation) "
                                     "{ return 1.0; }\n"});
    }

    static Inspection inspected(const std::string& filter) {
        Scene scene = load_scene(scene_file());
        scene.camera.aspect = static_cast<double>(kWidth) / kHeight;
        return inspect_scene(scene, {.method = "focused", .settings = {{"filter", filter}}, .resolution = 1024});
    }
};

nlohmann::json measured(const std::string& filter) {
    return nlohmann::json::parse(printed([&] {
        run_measure({.scene_file = scene_file(),
                     .method = "focused",
                     .settings = {{"filter", filter}},
                     .resolution = 512,
                     .width = 320,
                     .height = 180,
                     .json = true});
    }));
}

// The pixels the GPU pass's lit mask paints black: shadowed.
size_t shadowed_pixels(const Inspection& in) {
    ViewOptions options;
    options.lit_mask = true;
    const RgbImage mask = render_view(in, view_or_throw("camera"), options, kWidth, kHeight);
    size_t black = 0;
    for (int y = 0; y < mask.height; ++y)
        for (int x = 0; x < mask.width; ++x) {
            const unsigned char* c = mask.at(x, y);
            black += c[0] < 64 && c[1] < 64 && c[2] < 64;
        }
    return black;
}

}  // namespace

TEST_F(FilterExtension, MeasureReadsItAndFindsNoShadowWhereTheReferenceHasSome) {
    const nlohmann::json mine = measured("lit_everywhere"), hard = measured("hard");
    EXPECT_EQ(mine["lookup"]["filter"]["kind"], "lit_everywhere");
    EXPECT_EQ(mine["lookup"]["filter"]["taps"], 0);
    // Shares of the receiver pixels: none judged shadowed, the box's whole shadow judged lit.
    EXPECT_EQ(mine["false_shadow"].get<double>(), 0.0);
    EXPECT_GT(mine["false_light"].get<double>(), 0.001) << "the box's shadow, every pixel of it judged lit";
    EXPECT_GT(mine["false_light"].get<double>(), 10 * hard["false_light"].get<double>());
}

TEST_F(FilterExtension, RenderAndTheGpuPassLightEveryPixel) {
    const std::string out = ::testing::TempDir() + "lit_everywhere_camera.png";
    std::filesystem::remove(out);
    run_render({.scene_file = scene_file(),
                .method = "focused",
                .settings = {{"filter", "lit_everywhere"}},
                .view = "camera",
                .width = 320,
                .height = 180,
                .resolution = 512,
                .out = out});
    EXPECT_TRUE(std::filesystem::exists(out));

    const Inspection mine = inspected("lit_everywhere"), hard = inspected("hard");
    EXPECT_EQ(mine.lookup.filter.kind, "lit_everywhere");
    EXPECT_GT(shadowed_pixels(hard), 100u) << "the box's shadow beside it, and its faces away from the light";
    EXPECT_EQ(shadowed_pixels(mine), 0u);
    const Agreement gpu = gpu_against_cpu_lookup(mine, kWidth, kHeight);
    ASSERT_GT(gpu.compared, kWidth * kHeight / 4u);
    EXPECT_EQ(gpu.agreed, gpu.compared);
}

TEST_F(FilterExtension, TheControlsPanelOffersItAndChoosingItRendersNoShadow) {
    ControlsPanel controls;
    controls.set_method("focused");
    auto* filter = controls.findChild<QComboBox*>("filter");
    ASSERT_NE(filter, nullptr);
    ASSERT_GE(filter->findText("lit_everywhere"), 0) << "the chooser offers every registered filter";
    filter->setCurrentText("lit_everywhere");
    const InspectionRequest request = controls.request();
    EXPECT_EQ(request.settings.at("filter"), "lit_everywhere");
    EXPECT_FALSE(request.settings.count("kernel_size")) << "a setting the filter does not read is not requested";

    Scene scene = load_scene(scene_file());
    scene.camera.aspect = static_cast<double>(kWidth) / kHeight;
    const Inspection chosen = inspect_scene(scene, request);
    EXPECT_EQ(chosen.lookup.filter.kind, "lit_everywhere");
    EXPECT_EQ(shadowed_pixels(chosen), 0u);
}

TEST_F(FilterExtension, AnUnknownFilterIsANamedError) {
    try {
        filter_named("no_such_filter");
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("unknown filter 'no_such_filter'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("lit_everywhere"), std::string::npos) << e.what();
    }
    EXPECT_THROW(register_filter({.name = "Not-GLSL", .taps = no_taps, .texel_reads = no_reads, .visibility = lit}),
                 std::invalid_argument);
}
