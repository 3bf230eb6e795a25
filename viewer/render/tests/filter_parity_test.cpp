// The GPU pass reads shadows as the one CPU lookup does (issue 15): for each filter and each depth
// bias, and each depth format (issue 26), the pass's visibility per pixel
// (ShadowMapPass::Output::visibility, a grey level) against ShadowReader::visibility of the same
// receiver: the visible point, its normal, the Poisson disk's turn at that pixel.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>
#include <gtest/gtest.h>

#include "view_test_support.hpp"
#include "lookup/shadow_filter.hpp"
#include "views/view.hpp"
#include "visibility_parity.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kWidth = 480, kHeight = 270;
using SettingTexts = std::map<std::string, std::string>;

// The floating box under a sun 2° in angular radius, the camera nearer than floating_box's: the
// shadow's penumbrae several texels and pixels wide, so that PCSS's search and penumbra both matter.
Scene box_under_area_sun() {
    Scene scene = floating_box(kWidth, kHeight);
    scene.light.angular_radius_deg = 2.0;
    scene.camera.position = {0.0, 5.0, 6.0};
    scene.camera.target = {0.0, 0.5, 0.0};
    return scene;
}

struct SettingsCase {
    std::string name;
    SettingTexts settings;
};

const SettingsCase kFilters[] = {
    {"hard", {{"filter", "hard"}}},
    {"pcf box 3", {{"filter", "pcf"}, {"pcf_kernel", "box"}, {"kernel_size", "3"}, {"filter_radius", "2"}}},
    {"pcf tent 3", {{"filter", "pcf"}, {"pcf_kernel", "tent"}, {"kernel_size", "3"}, {"filter_radius", "2"}}},
    {"pcf poisson 4", {{"filter", "pcf"}, {"pcf_kernel", "poisson"}, {"kernel_size", "4"}, {"filter_radius", "3"}}},
    {"vsm", {{"filter", "vsm"}, {"kernel_size", "5"}}},
    {"evsm", {{"filter", "evsm"}, {"kernel_size", "5"}}},
    {"msm", {{"filter", "msm"}, {"kernel_size", "5"}}},
    {"msm 16 bits", {{"filter", "msm"}, {"kernel_size", "5"}, {"msm_quantization", "unorm16"}}},
    // ESM at its default c = 80 lights a receiver wherever the blur holds one empty texel (its e^{c}
    // at the far plane, the ground casting nothing here): a ramp under a pixel wide. c = 10 widens it.
    {"esm", {{"filter", "esm"}, {"kernel_size", "5"}, {"esm_exponent", "10"}}},
    {"pcss", {{"filter", "pcss"}, {"kernel_size", "4"}}},
};

const SettingsCase kBiases[] = {
    {"slope-scaled", {}},
    {"normal offset 1", {{"bias_normal", "1"}}},
    {"receiver plane", {{"bias_receiver_plane", "on"}}},
};

// Every filter with one more lookup setting (a bias, a depth format) against the CPU's visibility.
template <class Variants>
void expect_each_filter_to_read_as_the_cpu(const Variants& variants) {
    const Scene scene = box_under_area_sun();
    const ReferenceImage ref = exact_reference(scene, tessellate(scene), kWidth, kHeight);
    for (const SettingsCase& filter : kFilters) {
        for (const SettingsCase& variant : variants) {
            InspectionRequest request{.method = "focused", .settings = filter.settings, .resolution = 1024};
            request.settings.insert(variant.settings.begin(), variant.settings.end());
            const VisibilityParity p = gpu_against_cpu_visibility(inspect_scene(scene, request), ref);
            const std::string name = filter.name + ", " + variant.name;
            ASSERT_GT(p.compared, kWidth * kHeight / 4u) << name;
            EXPECT_GT(p.shadowed, 1000u) << name << ": the box's shadow is in view";
            if (filter.settings.at("filter") != "hard") {
                EXPECT_GT(p.penumbra, 100u) << name << ": the filter softens";
            }
            EXPECT_LT(p.mean_difference, 0.02) << name;
            EXPECT_LT(p.penumbra_mean_difference, 0.02) << name << ", in the penumbrae";
            std::cout << name << ": mean |GPU - CPU| visibility " << p.mean_difference << " over " << p.compared
                      << " pixels, " << p.penumbra_mean_difference << " over the " << p.penumbra << " in a penumbra ("
                      << p.shadowed << " less than half lit)\n";
        }
    }
}

}  // namespace

// The cases hold every shipped filter: a filter added to the list is added here too.
TEST(GpuFilterParity, TheCasesHoldEveryFilter) {
    for (const FilterDescriptor& f : all_filters())
        EXPECT_TRUE(std::any_of(std::begin(kFilters), std::end(kFilters), [&](const SettingsCase& c) {
            return c.settings.at("filter") == f.name;
        })) << f.name;
}

TEST(GpuFilterParity, EachFilterAndBiasReadsAsTheCpuLookup) { expect_each_filter_to_read_as_the_cpu(kBiases); }

// Every depth format but the default, under the default bias: each filter reads the map back as d
// (reversed: 1 − s), the moments of VSM and EVSM summed from it too.
TEST(GpuFilterParity, EachFilterReadsEachDepthFormatAsTheCpuLookup) {
    std::vector<SettingsCase> formats;
    for (const DepthFormat& format : depth_formats())
        if (!(format == DepthFormat{})) formats.push_back({describe(format), depth_format_settings(format)});
    ASSERT_EQ(formats.size(), 5u);
    expect_each_filter_to_read_as_the_cpu(formats);
}
