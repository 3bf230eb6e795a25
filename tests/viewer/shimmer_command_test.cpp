// `shadowlab shimmer` as a user runs it: a CSV row per frame and a plot; bad options refused by name.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "shimmer_command.hpp"

using namespace shadowlab;

namespace {

ShimmerOptions small_run(const std::string& method) {
    return {.scene_file = std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/box_on_plane.json",
            .method = method,
            .frames = 5,
            .resolution = 256,
            .width = 160,
            .height = 90,
            .out_dir = ::testing::TempDir() + "shimmer_" + method + std::to_string(getpid())};
}

void expect_refused(ShimmerOptions o, const std::string& option) {
    try {
        run_shimmer(o);
        ADD_FAILURE() << option << " was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(option), std::string::npos) << e.what();
    }
}

}  // namespace

TEST(ShimmerCommand, WritesARowPerFrameAndThePlot) {
    const ShimmerOptions o = small_run("uniform");
    run_shimmer(o);
    std::ifstream csv(std::filesystem::path(o.out_dir) / "shimmer.csv");
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line,
              "frame,judged,wrong,transitions,flips,pages_allocated,pages_kept,pages_freed,texels_fresh,texels_cached,"
              "fallback");
    int rows = 0;
    while (std::getline(csv, line)) {
        ++rows;
        std::vector<std::string> fields;
        std::stringstream row(line);
        for (std::string field; std::getline(row, field, ',');) fields.push_back(field);
        ASSERT_EQ(fields.size(), 11u) << line;
        EXPECT_EQ(fields[4], "0") << "uniform's map does not follow the camera: no flip: " << line;
        // No page table: nothing allocated or kept, and every texel drawn each frame, cache or none.
        EXPECT_EQ(fields[5] + fields[6] + fields[7], "000") << line;
        EXPECT_EQ(fields[8], std::to_string(o.resolution * o.resolution)) << line;
        EXPECT_EQ(fields[8], fields[9]) << line;
    }
    EXPECT_EQ(rows, o.frames);
    EXPECT_GT(std::filesystem::file_size(std::filesystem::path(o.out_dir) / "shimmer.png"), 1000u);
}

TEST(ShimmerCommand, BadOptionsAreRefusedByName) {
    ShimmerOptions o = small_run("focused");
    o.path = "orbit";
    expect_refused(o, "--path");
    o = small_run("focused");
    o.frames = 1;
    expect_refused(o, "--frames");
    o = small_run("volumes");
    expect_refused(o, "volumes");
}
