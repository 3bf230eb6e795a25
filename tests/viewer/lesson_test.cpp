// `shadowlab lesson`: a course page with every step's title, formula, values and pictures, its
// matrices laid out as computed or as the papers print them.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <regex>
#include <map>
#include <sstream>

#include "io/value_text.hpp"
#include "lesson_command.hpp"
#include "math/matrix.hpp"
#include "metrics/diagnosis.hpp"
#include "model/inspection.hpp"
#include "render/rgb_image.hpp"
#include "scene/image_size.hpp"
#include "scene/scene_loader.hpp"

using namespace shadowlab;

namespace {

const std::string kScene = std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/box_on_plane.json";

std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The share of pixels in the image's most common colour (1: one flat colour).
double commonest_colour_share(const RgbImage& image) {
    std::map<std::array<unsigned char, 3>, size_t> counts;
    size_t most = 0;
    for (size_t i = 0; i < image.rgb.size(); i += 3)
        most = std::max(most, ++counts[{image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]}]);
    return static_cast<double>(most) / (image.rgb.size() / 3);
}

// The first row of the 4 x 4 table that follows the value's name on the page.
std::vector<std::string> first_matrix_row(const std::string& html, const std::string& name) {
    const size_t at = html.find("<th>" + name + "</th>");
    const std::string after = html.substr(at);
    const std::regex cell(R"(<td title="[^"]*">([^<]*)</td>)");
    std::vector<std::string> cells;
    for (auto it = std::sregex_iterator(after.begin(), after.end(), cell);
         it != std::sregex_iterator() && cells.size() < 4; ++it)
        cells.push_back((*it)[1]);
    return cells;
}

LessonOptions lesson_into(const std::string& name, bool row_vectors) {
    return {.scene_file = kScene,
            .method = "lispsm",
            .resolution = 256,
            .width = 200,
            .height = 130,
            .row_vectors = row_vectors,
            .out = ::testing::TempDir() + name + std::to_string(getpid())};
}

}  // namespace

TEST(Lesson, EveryStepHasItsTitleFormulaValuesAndPictures) {
    const LessonOptions options = lesson_into("lesson_columns_", false);
    const int pictures = run_lesson(options);
    const std::string html = read_text(std::filesystem::path(options.out) / "index.html");
    const Inspection in = inspect_scene(load_scene(kScene), {.method = "lispsm", .resolution = 256});
    size_t matrices = 0;
    for (const Step& step : in.trace.steps()) {
        EXPECT_NE(html.find(step.title), std::string::npos) << step.id;
        EXPECT_NE(html.find("id=\"" + step.id + "\""), std::string::npos) << step.id;
        for (const NamedValue& v : step.values) matrices += std::holds_alternative<glm::dmat4>(v.value);
    }
    size_t tables = 0;
    for (size_t at = html.find("class=\"matrix\""); at != std::string::npos; at = html.find("class=\"matrix\"", at + 1))
        ++tables;
    EXPECT_EQ(tables, matrices);

    // Every picture the page shows exists and draws something (not one flat colour); every step has one.
    const std::regex image(R"re(<img src="([^"]+)")re");
    int shown = 0;
    for (auto it = std::sregex_iterator(html.begin(), html.end(), image); it != std::sregex_iterator(); ++it, ++shown) {
        const RgbImage picture = read_png((std::filesystem::path(options.out) / (*it)[1].str()).string());
        EXPECT_LT(commonest_colour_share(picture), 0.9) << (*it)[1];
    }
    EXPECT_EQ(shown, pictures);
    EXPECT_GE(pictures, static_cast<int>(in.trace.steps().size()));
}

// Ours print p' = M p with the projection in the last row; the papers print the transpose.
TEST(Lesson, MatricesAsComputedOrAsThePapersPrintThem) {
    const Inspection in = inspect_scene(load_scene(kScene), {.method = "lispsm", .resolution = 256});
    const glm::dmat4 world_to_uvz = in.setup.maps.front().world_to_uvz;
    for (const bool row_vectors : {false, true}) {
        const LessonOptions options = lesson_into(row_vectors ? "lesson_rows_" : "lesson_cols_", row_vectors);
        run_lesson(options);
        const std::vector<std::string> cells =
            first_matrix_row(read_text(std::filesystem::path(options.out) / "index.html"), "world_to_uvz");
        ASSERT_EQ(cells.size(), 4u);
        const glm::dvec4 expected = row_vectors ? world_to_uvz[0] : row(world_to_uvz, 0);
        for (int c = 0; c < 4; ++c) EXPECT_EQ(cells[c], significant(expected[c], 4)) << "column " << c;
    }
}

// "What goes wrong": with no bias at all, acne over the box's lit faces leads the causes; the
// table ranks them as the inspection's own error over the pictures' camera image does, and the
// Error view by cause is shown beside it.
TEST(Lesson, WhatGoesWrongRanksTheCausesTheCommonestFirst) {
    LessonOptions options = lesson_into("lesson_wrong_", false);
    options.method = "psm";
    options.settings = {{"bias_slope", "0"}};
    run_lesson(options);
    const std::string html = read_text(std::filesystem::path(options.out) / "index.html");
    const size_t at = html.find("<section id=\"what-goes-wrong\"><h2>What goes wrong</h2>");
    ASSERT_NE(at, std::string::npos);
    const std::string section = html.substr(at);

    const Scene scene = load_scene(kScene);
    const glm::ivec2 image = image_size_within(scene.camera, options.width, options.height);
    const Inspection in = inspect_scene(scene, {.method = options.method,
                                                .settings = options.settings,
                                                .resolution = options.resolution,
                                                .image_width = image.x,
                                                .image_height = image.y});
    const Diagnosis d = count_causes(in.error(image.x, image.y));
    ASSERT_FALSE(d.causes.empty());
    EXPECT_EQ(d.causes.front().kind, PixelCause::acne);

    std::smatch first;
    ASSERT_TRUE(
        std::regex_search(section, first,
                          std::regex(R"re(<tr><td><span class="swatch"[^>]*></span><code>([a-z_]+)</code></td>)re"
                                     R"re(<td class="number">([0-9]+)</td>)re")));
    EXPECT_EQ(first[1].str(), to_string(d.causes.front().kind));
    EXPECT_EQ(std::stoul(first[2].str()), d.causes.front().pixels);
    EXPECT_NE(section.find("bias_slope 0 → 1"), std::string::npos) << "the acne's remedy";
    EXPECT_NE(section.find("<img src=\"what-goes-wrong-error-causes.png\""), std::string::npos);
}

TEST(Lesson, AMissingOutputDirectoryIsRefusedByName) {
    LessonOptions options = lesson_into("unused_", false);
    options.out.clear();
    EXPECT_THROW(
        {
            try {
                run_lesson(options);
            } catch (const std::invalid_argument& e) {
                EXPECT_NE(std::string(e.what()).find("--out"), std::string::npos);
                throw;
            }
        },
        std::invalid_argument);
}
