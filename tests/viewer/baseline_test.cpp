// Image baselines, as F3D tests its renderer: a handful of views drawn offscreen and compared with
// reference PNGs in tests/baselines within a tolerance. On failure the drawn image and a difference
// image are written beside the test's temporary files and named in the message. After an intended
// change of a picture, look at the new images, then refresh the references with
//   SHADOWLAB_UPDATE_BASELINES=1 xvfb-run -a ./build/tests/shadowlab_viewer_tests --gtest_filter='Baseline*'
#include <cstdlib>
#include <filesystem>
#include <gtest/gtest.h>

#include "render/rgb_image.hpp"
#include "scene/image_size.hpp"
#include "scene/scene_loader.hpp"
#include "views/offscreen_view.hpp"

using namespace shadowlab;

namespace {

const std::filesystem::path kBaselines = std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "tests/baselines";

// A pixel differs when one of its channels differs by more than this; an image fails when more
// than kMaxDifferingShare of its pixels differ (Mesa versions shift edges by a pixel or two).
constexpr int kChannelTolerance = 48;
constexpr double kMaxDifferingShare = 0.01;

struct Baseline {
    const char* name;  // tests/baselines/NAME.png
    const char* scene;
    const char* method;
    const char* view;  // its name
    ViewOptions options;
};

const Baseline kBaselineViews[] = {
    {"camera_focused_teaching", "teaching.json", "focused", "camera", {}},
    {"camera_volumes_teaching", "teaching.json", "volumes", "camera", {}},
    {"world_lispsm_body", "box_on_plane.json", "lispsm", "world", {.step = "body"}},
    {"light_side_lispsm_gamma", "box_on_plane.json", "lispsm", "light", {.step = "gamma", .preset = SpacePreset::side}},
    {"ppls_side_lispsm_warp", "box_on_plane.json", "lispsm", "ppls", {.step = "warp", .preset = SpacePreset::side}},
    {"ppls_light_xpsm_focus",
     "box_on_plane.json",
     "xpsm",
     "ppls",
     {.step = "xpsm-13", .preset = SpacePreset::from_light}},
    {"shadowmap_xpsm_default", "default.json", "xpsm", "shadowmap", {}},
    {"error_lispsm_default", "default.json", "lispsm", "error", {}},
    {"error_causes_lispsm_default", "default.json", "lispsm", "error", {.error = ErrorShown::causes}},
};

void PrintTo(const Baseline& b, std::ostream* out) { *out << b.name; }

RgbImage draw(const Baseline& b) {
    const Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/" + b.scene);
    const glm::ivec2 camera_image = image_size_within(scene.camera, 400, 250);
    const Inspection in = inspect_scene(
        scene, {.method = b.method, .resolution = 1024, .image_width = camera_image.x, .image_height = camera_image.y});
    const View& view = view_or_throw(b.view);
    const glm::ivec2 size = view.interaction.through_scene_camera ? camera_image : glm::ivec2(400, 250);
    return render_view(in, view, b.options, size.x, size.y);
}

// Each pixel's largest channel difference, amplified, and the share above the tolerance.
struct Difference {
    RgbImage image;
    double differing_share = 1.0;
};

Difference difference(const RgbImage& drawn, const RgbImage& reference) {
    Difference d{RgbImage(drawn.width, drawn.height)};
    if (drawn.width != reference.width || drawn.height != reference.height) return d;
    size_t differing = 0;
    for (size_t i = 0; i < drawn.rgb.size(); i += 3) {
        int largest = 0;
        for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(drawn.rgb[i + c] - reference.rgb[i + c]));
        differing += largest > kChannelTolerance;
        for (int c = 0; c < 3; ++c) d.image.rgb[i + c] = static_cast<unsigned char>(std::min(255, 4 * largest));
    }
    d.differing_share = static_cast<double>(differing) / (drawn.rgb.size() / 3);
    return d;
}

class BaselineTest : public ::testing::TestWithParam<Baseline> {};

}  // namespace

TEST_P(BaselineTest, ViewMatchesItsReferenceImage) {
    const Baseline& b = GetParam();
    const RgbImage drawn = draw(b);
    const std::filesystem::path reference = kBaselines / (std::string(b.name) + ".png");
    if (std::getenv("SHADOWLAB_UPDATE_BASELINES")) {
        write_png(drawn, reference.string());
        GTEST_SKIP() << "wrote " << reference;
    }
    ASSERT_TRUE(std::filesystem::exists(reference)) << reference << " is missing: see this file's header";
    const Difference d = difference(drawn, read_png(reference.string()));
    if (d.differing_share > kMaxDifferingShare) {
        const std::string out = ::testing::TempDir() + b.name;
        write_png(drawn, out + "_drawn.png");
        write_png(d.image, out + "_difference.png");
        ADD_FAILURE() << b.name << ": " << 100 * d.differing_share << " % of pixels differ from " << reference
                      << " (tolerance " << 100 * kMaxDifferingShare << " %); drawn: " << out
                      << "_drawn.png, difference: " << out << "_difference.png";
    }
}

INSTANTIATE_TEST_SUITE_P(Views, BaselineTest, ::testing::ValuesIn(kBaselineViews),
                         [](const ::testing::TestParamInfo<Baseline>& info) { return std::string(info.param.name); });
