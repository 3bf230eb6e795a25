// `shadowlab compare`: two configurations against one reference. Its files are written, each run's
// numbers are `measure --json`'s for that method, the comparison adds up to each run's misclassified
// pixels and is the Difference view's, one method with two settings is expressible, and bad input
// is one line naming the option with a non-zero exit.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>

#include "cli_support.hpp"
#include "compare_command.hpp"
#include "metrics/verdict_comparison.hpp"
#include "model/inspection.hpp"
#include "render/rgb_image.hpp"
#include "scene/scene_loader.hpp"
#include "views/difference_colours.hpp"

using namespace shadowlab;
using shadowlab::testing::run_cli;

namespace {

const std::string kScene = std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/default.json";

const std::string kCliHint = "Run with --help";

std::string out_dir(const std::string& name) { return ::testing::TempDir() + "compare_" + name; }

CompareOptions focused_against_lispsm(const std::string& name) {
    return {.scene_file = kScene,
            .methods = {"focused", "lispsm"},
            .resolution = 256,
            .width = 320,
            .height = 180,
            .out = out_dir(name)};
}

size_t pixels_of(const RgbImage& image, const difference_colours::Colour& colour) {
    size_t n = 0;
    for (size_t i = 0; i < image.rgb.size(); i += 3) n += std::equal(colour.begin(), colour.end(), &image.rgb[i]);
    return n;
}

// The measure's error numbers, which do not depend on timing.
void expect_same_error(const Json& compared, const nlohmann::json& measured, const std::string& method) {
    SCOPED_TRACE(method);
    EXPECT_EQ(compared["method"], measured["method"]);
    EXPECT_EQ(compared["receiver_pixels"], measured["receiver_pixels"]);
    for (const char* key : {"misclassified", "false_shadow", "false_light"})
        EXPECT_DOUBLE_EQ(compared[key].get<double>(), measured[key].get<double>()) << key;
    for (const char* key : {"max", "mean", "p95"})
        EXPECT_DOUBLE_EQ(compared["m"][key].get<double>(), measured["m"][key].get<double>()) << key;
    EXPECT_EQ(compared["diagnosis"]["misclassified_pixels"], measured["diagnosis"]["misclassified_pixels"]);
}

}  // namespace

TEST(CompareCommand, WritesItsFilesWithEachRunsMeasure) {
    const CompareOptions options = focused_against_lispsm("files");
    std::filesystem::remove_all(options.out);
    const Json json = run_compare(options);
    for (const char* file :
         {"difference.png", "compare.json", "compare.md", "lesson.html", "error-causes-A.png", "error-causes-B.png"})
        EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(options.out) / file)) << file;

    // Each side is what `measure --json` prints for its method on the same image and resolution.
    for (const auto& [side, method] : {std::pair{"a", "focused"}, std::pair{"b", "lispsm"}}) {
        const auto result =
            run_cli("measure " + kScene + " --method " + method + " --resolution 256 --size 320x180 --json");
        ASSERT_EQ(result.exit_code, 0) << result.err;
        expect_same_error(json[side], nlohmann::json::parse(result.out), method);
    }

    // The comparison's classes are each run's misclassified pixels split by what the other did.
    const Json& c = json["comparison"];
    const size_t receivers = c["receiver_pixels"];
    ASSERT_GT(receivers, 1000u);
    const size_t both_right = c["both_right"], both_wrong = c["both_wrong"], only_a = c["only_a_right"],
                 only_b = c["only_b_right"];
    EXPECT_EQ(both_right + both_wrong + only_a + only_b, receivers);
    EXPECT_EQ(both_wrong + only_b, json["a"]["diagnosis"]["misclassified_pixels"].get<size_t>());
    EXPECT_EQ(both_wrong + only_a, json["b"]["diagnosis"]["misclassified_pixels"].get<size_t>());
    EXPECT_GT(only_a + only_b, 0u);

    // The picture is the Difference view of the same two runs: its classes are the JSON's, and each
    // class present is painted (where the verdicts differ, grown to 3x3 blocks, one over another).
    const Scene scene = load_scene(kScene);
    const auto inspected = [&](const std::string& method) {
        return inspect_scene(scene, {.method = method, .resolution = 256, .image_width = 320, .image_height = 180});
    };
    const Inspection a = inspected("focused"), b = inspected("lispsm");
    const VerdictComparison drawn = compare_verdicts(a.error(320, 180), b.error(320, 180));
    EXPECT_EQ(to_json(drawn), c);
    const RgbImage png = read_png(options.out + "/difference.png");
    ASSERT_EQ(png.width, 320);
    // (The legend and the caption cover a third of a 320x180 picture, and the blocks cover more.)
    EXPECT_GT(pixels_of(png, difference_colours::kBothRight), both_right / 4);
    EXPECT_GE(pixels_of(png, difference_colours::kOnlyARight), only_a / 2);
    EXPECT_GE(pixels_of(png, difference_colours::kOnlyBRight), only_b / 2);
    EXPECT_GT(pixels_of(png, difference_colours::kOnlyARight) + pixels_of(png, difference_colours::kOnlyBRight), 0u);

    const std::string md = shadowlab::testing::slurp(options.out + "/compare.md");
    EXPECT_NE(md.find("| only A right | " + std::to_string(only_a) + " |"), std::string::npos) << md;
    const std::string lesson = shadowlab::testing::slurp(options.out + "/lesson.html");
    EXPECT_NE(lesson.find("id=\"what-goes-wrong-A\""), std::string::npos);
    EXPECT_NE(lesson.find("id=\"what-goes-wrong-B\""), std::string::npos);
}

// One method, two settings: B reads with PCF, A with the default hard lookup.
TEST(CompareCommand, OneMethodWithTwoSettings) {
    CompareOptions options = focused_against_lispsm("settings");
    options.methods = {"lispsm", "lispsm"};
    options.settings_b = {{"filter", "pcf"}};
    const Json json = run_compare(options);
    EXPECT_EQ(json["a"]["lookup"]["filter"]["kind"], "hard");
    EXPECT_EQ(json["b"]["lookup"]["filter"]["kind"], "pcf");
    EXPECT_GT(json["comparison"]["differing"].get<size_t>(), 0u);
}

TEST(CompareCommand, BadInputIsOneLineNamingTheOption) {
    const std::string out = " --size 64x36 --resolution 128 --out " + out_dir("bad");
    for (const auto& [args, named] :
         {std::pair{"--methods focused", "--methods"}, std::pair{"--methods focused,nosuch", "--methods"},
          std::pair{"--methods focused,lispsm --set-b nosuch=1", "--set-b"},
          std::pair{"--methods focused,lispsm --set-a filter", "--set-a"},
          std::pair{"--methods focused,focused --set filter=blurry", "--set"}}) {
        const auto result = run_cli("compare " + kScene + " " + args + out);
        EXPECT_NE(result.exit_code, 0) << args;
        EXPECT_NE(result.err.find(named), std::string::npos) << args << ": " << result.err;
        const std::string error = result.err.substr(0, result.err.find(kCliHint));  // CLI11's hint after its own
        EXPECT_EQ(std::count(error.begin(), error.end(), '\n'), 1) << args << ": " << result.err;
    }
}
