// `shadowlab render` as a user runs it: the issue's own command writes a picture with visible
// shadows; a bad view is refused by name.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <vtkImageData.h>

#include "../cli_support.hpp"
#include "render/rgb_image.hpp"

using namespace shadowlab;
using shadowlab::testing::run_cli;

namespace {

std::string scene(const std::string& name) { return std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/" + name; }

}  // namespace

TEST(RenderCommand, DefaultSceneCameraViewHasVisibleShadows) {
    const std::string out = ::testing::TempDir() + "shot_" + std::to_string(getpid()) + ".png";
    const auto r = run_cli("render " + scene("default.json") + " --method focused --view camera --out " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const RgbImage image = read_png(out);
    ASSERT_EQ(image.width, 1280);
    ASSERT_EQ(image.height, 720);
    // The ground fills the lower half: shadowed and lit parts are both a clear share of it.
    std::vector<double> brightness;
    for (int y = image.height / 2; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const unsigned char* c = image.at(x, y);
            brightness.push_back((c[0] + c[1] + c[2]) / 3.0);
        }
    std::sort(brightness.begin(), brightness.end());
    const double bright = brightness[brightness.size() * 9 / 10];
    const auto dark = std::count_if(brightness.begin(), brightness.end(), [&](double b) { return b < 0.6 * bright; });
    const double dark_share = static_cast<double>(dark) / brightness.size();
    EXPECT_GT(dark_share, 0.05) << "no shadow on the ground";
    EXPECT_LT(dark_share, 0.95) << "no lit ground";
    std::filesystem::remove(out);
}

TEST(RenderCommand, UnknownViewIsRefusedByName) {
    const auto r = run_cli("render " + scene("box_on_plane.json") + " --view sideways --out /tmp/never.png");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("--view: unknown view 'sideways'"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists("/tmp/never.png"));
}

// The Camera view keeps the scene camera's aspect: asked for 320x180, a square camera's picture is
// 180x180 (and says so); views that are not the camera's picture fill the asked size.
TEST(RenderCommand, CameraViewKeepsTheCamerasAspect) {
    const std::string square = ::testing::TempDir() + "square_render.json";
    {
        nlohmann::json json = nlohmann::json::parse(shadowlab::testing::slurp(scene("box_on_plane.json")));
        json["camera"]["aspect"] = 1.0;
        std::ofstream(square) << json.dump();
    }
    const std::string out = ::testing::TempDir() + "square_" + std::to_string(getpid()) + ".png";
    for (const auto& [view, width, height] : {std::tuple{"camera", 180, 180}, std::tuple{"world", 320, 180}}) {
        const auto r =
            run_cli("render " + square + " --view " + view + " --size 320x180 --resolution 256 --out " + out);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const RgbImage image = read_png(out);
        EXPECT_EQ(image.width, width) << view;
        EXPECT_EQ(image.height, height) << view;
        EXPECT_NE(r.err.find(std::to_string(width) + "x" + std::to_string(height)), std::string::npos) << r.err;
    }
    std::filesystem::remove(out);
}
