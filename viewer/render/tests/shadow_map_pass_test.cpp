// The shadow-map pass checked on its pixels under Xvfb: shadows where the map puts them for every
// map method and technique, and the GPU lookup against the CPU lookup (core/maps/map_lookup).
#include <array>
#include <iostream>
#include <gtest/gtest.h>

#include "metrics/shadow_error.hpp"
#include "reference/exact_shadows.hpp"
#include "registry/method.hpp"
#include "scene/scene_loader.hpp"
#include "view_test_support.hpp"
#include "views/offscreen_view.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kWidth = 480, kHeight = 270;

}  // namespace

class CameraViewOfEachMethod : public ::testing::TestWithParam<std::string> {};

// Every map method and every geometric technique (the stencil pass).
TEST_P(CameraViewOfEachMethod, GroundUnderTheBoxIsDarkerThanGroundFarFromIt) {
    const Scene scene = floating_box(kWidth, kHeight);
    const Inspection in = inspect(scene, GetParam(), 1024);
    const RgbImage image = render_view(in, ViewKind::camera, {}, kWidth, kHeight);
    ASSERT_EQ(image.width, kWidth);
    const double under = brightness(image, pixel_of(scene.camera, {0.0, 0.0, 0.0}, kWidth, kHeight));
    const double away = brightness(image, pixel_of(scene.camera, {6.0, 0.0, -3.0}, kWidth, kHeight));
    EXPECT_GT(away, 80.0) << "the lit ground should be drawn";
    EXPECT_LT(under, 0.7 * away) << GetParam() << ": under the box " << under << ", away " << away;
}

INSTANTIATE_TEST_SUITE_P(AllMethods, CameraViewOfEachMethod, ::testing::ValuesIn([] {
                             std::vector<std::string> names;
                             for (const Method& m : all_methods()) names.push_back(m.name);
                             return names;
                         }()));

// Issue 5: the GPU pass and the CPU lookup agree on the visible pixels away from shadow edges.
class GpuAgreesWithCpu : public ::testing::TestWithParam<std::string> {};

TEST_P(GpuAgreesWithCpu, OnVisiblePixelsAwayFromShadowEdges) {
    Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/" + GetParam() + ".json");
    scene.camera.aspect = static_cast<double>(kWidth) / kHeight;
    for (const std::string method : {"focused", "lispsm", "xpsm"}) {
        const Agreement a = gpu_against_cpu_lookup(inspect(scene, method, 1024), kWidth, kHeight);
        ASSERT_EQ(a.undrawn, 0u) << "the GPU drew nothing where the reference sees something";
        ASSERT_GT(a.compared, kWidth * kHeight / 4u);
        EXPECT_GE(a.share(), 0.995) << method << " on " << GetParam() << ": " << a.compared - a.agreed << " of "
                                    << a.compared << " pixels differ";
        RecordProperty(method + "_agreement", std::to_string(a.share()));  // in the XML report
        std::cout << method << " on " << GetParam() << ": GPU and CPU agree on " << a.agreed << " of " << a.compared
                  << " pixels away from edges\n";
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, GpuAgreesWithCpu, ::testing::Values("box_on_plane", "default", "spot"));
