// `shadowlab shimmer` as a user runs it: a CSV row per frame and a plot; bad options refused by name.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>

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
    EXPECT_EQ(line, "frame,judged,wrong,transitions,flips,fallback");
    int rows = 0;
    while (std::getline(csv, line)) {
        ++rows;
        EXPECT_NE(line.find(",0,\""), std::string::npos)
            << "uniform's map does not follow the camera: no flip: " << line;
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
