// A virtual shadow map on the GPU (MapSelection::Rule::pages): far more pages than the pass's
// uniform arrays hold, each drawn into its slot of the pool, and each fragment's page picked from
// the page table in the fragment shader as resident_map picks it; the lit mask and each filter's
// visibility against the CPU lookup (ShadowReader) on the same pixels.
#include <cmath>
#include <iostream>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>
#include <gtest/gtest.h>
#include <vtkNew.h>

#include "render/shadow_map_pass.hpp"
#include "view_test_support.hpp"
#include "views/view.hpp"
#include "visibility_parity.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kWidth = 480, kHeight = 270;
using SettingTexts = std::map<std::string, std::string>;

// The levels that hold a resident page.
std::set<int> levels_with_pages(const ShadowSetup& setup) {
    std::set<int> levels;
    for (const PageAddress& a : setup.selection.pages.pages) levels.insert(a.level);
    return levels;
}

// The inspection's setup is a virtual map's: pages, more than the uniform arrays hold, over
// several levels (so that the GPU's choice of level is tested, not one page's alone).
void expect_many_pages(const Inspection& in) {
    ASSERT_EQ(in.setup.selection.rule, MapSelection::Rule::pages);
    EXPECT_GT(in.setup.maps.size(), static_cast<size_t>(ShadowMapPass::kMaxMaps));
    EXPECT_GE(levels_with_pages(in.setup).size(), 2u);
}

}  // namespace

// The lit mask against the CPU's verdicts on the shipped scenes, under the default settings (16
// levels, 128 pages per side: a table of 128 x 2048 texels) and a coarser pool of smaller pages.
TEST(GpuAgreesWithCpuOnVirtualMaps, LitMaskOnShippedScenes) {
    for (const std::string name : {"default", "box_on_plane"}) {  // sun-lit: a spot light takes one map
        const Scene scene = shipped_scene(name, kWidth, kHeight);
        for (const SettingTexts& settings :
             {SettingTexts{}, SettingTexts{{"page_size", "64"}, {"virtual_resolution", "8192"}}}) {
            const Inspection in = inspect_scene(scene, {.method = "virtual", .settings = settings, .resolution = 2048});
            expect_many_pages(in);
            const Agreement a = gpu_against_cpu_lookup(in, kWidth, kHeight);
            ASSERT_EQ(a.undrawn, 0u);
            ASSERT_GT(a.compared, kWidth * kHeight / 4u);
            const std::string what = name + (settings.empty() ? "" : ", pages of 64");
            EXPECT_GE(a.share(), 0.995) << what << ": " << a.compared - a.agreed << " of " << a.compared
                                        << " pixels differ";
            RecordProperty("virtual_agreement_" + name + (settings.empty() ? "" : "_64"), std::to_string(a.share()));
            std::cout << "virtual on " << what << " (" << in.setup.maps.size() << " pages over "
                      << levels_with_pages(in.setup).size() << " levels): GPU and CPU agree on " << a.agreed << " of "
                      << a.compared << " pixels away from edges\n";
        }
    }
}

// Every depth format, reversed Z included: each page drawn with its reversed depth and read back
// as the CPU reads it.
TEST(GpuAgreesWithCpuOnVirtualMaps, LitMaskInEachDepthFormat) {
    const Scene scene = shipped_scene("default", kWidth, kHeight);
    const std::vector<DepthFormat> formats = depth_formats();
    ASSERT_EQ(formats.size(), 6u);
    for (const DepthFormat& format : formats) {
        const Inspection in =
            inspect_scene(scene, {.method = "virtual", .settings = depth_format_settings(format), .resolution = 2048});
        ASSERT_EQ(in.depth().format, format);
        expect_many_pages(in);
        const Agreement a = gpu_against_cpu_lookup(in, kWidth, kHeight);
        ASSERT_EQ(a.undrawn, 0u);
        ASSERT_GT(a.compared, kWidth * kHeight / 4u);
        EXPECT_GE(a.share(), 0.995) << describe(format) << ": " << a.compared - a.agreed << " of " << a.compared
                                    << " pixels differ";
        std::cout << "virtual on default, " << describe(format) << ": GPU and CPU agree on " << a.agreed << " of "
                  << a.compared << " pixels away from edges\n";
    }
}

// Each filter reads through the page the CPU reads, its taps kept in the page's tile: the
// visibility per pixel against ShadowReader's, on the floating box (its shadow in view, a sun 2° wide
// for PCSS).
TEST(GpuAgreesWithCpuOnVirtualMaps, EachFilterReadsThePagesAsTheCpuLookup) {
    Scene scene = floating_box(kWidth, kHeight);
    scene.light.angular_radius_deg = 2.0;
    const std::vector<std::pair<std::string, SettingTexts>> filters = {
        {"hard", {{"filter", "hard"}}},
        {"pcf box 3", {{"filter", "pcf"}, {"pcf_kernel", "box"}, {"kernel_size", "3"}, {"filter_radius", "2"}}},
        {"pcf poisson 4", {{"filter", "pcf"}, {"pcf_kernel", "poisson"}, {"kernel_size", "4"}, {"filter_radius", "3"}}},
        {"pcss", {{"filter", "pcss"}, {"kernel_size", "4"}}},
        {"vsm", {{"filter", "vsm"}, {"kernel_size", "5"}}},
        {"evsm", {{"filter", "evsm"}, {"kernel_size", "5"}}},
        {"hard, receiver plane", {{"filter", "hard"}, {"bias_receiver_plane", "on"}}},
    };
    for (const auto& [name, settings] : filters) {
        const Inspection in = inspect_scene(scene, {.method = "virtual", .settings = settings, .resolution = 2048});
        expect_many_pages(in);
        const VisibilityParity p = gpu_against_cpu_visibility(in, in.reference(kWidth, kHeight));
        ASSERT_GT(p.compared, kWidth * kHeight / 4u) << name;
        EXPECT_GT(p.shaded, 500u) << name << ": the box's shadow is in view";
        EXPECT_LT(p.mean_difference, 0.02) << name;
        if (name.rfind("hard", 0) != 0) {
            EXPECT_GT(p.penumbra, 100u) << name << ": the filter softens";
            EXPECT_LT(p.penumbra_mean_difference, 0.03) << name << ", in the penumbrae";
        }
        std::cout << "virtual, " << name << ": mean |GPU - CPU| visibility " << p.mean_difference << " over "
                  << p.compared << " pixels, " << p.penumbra_mean_difference << " over the " << p.penumbra
                  << " in a penumbra (" << p.shaded << " not fully lit; " << in.setup.maps.size() << " pages)\n";
    }
}

// Small pages under soft shadows: most penumbrae straddle page edges, where a filter's taps read the
// neighbouring page (tap_texel on the CPU, shadowPageTapTexel on the GPU); GPU and CPU agree there.
TEST(GpuAgreesWithCpuOnVirtualMaps, FilterTapsReadAcrossPageEdgesAsTheCpuDoes) {
    const Scene scene = shipped_scene("soft_shadows", kWidth, kHeight);
    const std::vector<std::pair<std::string, SettingTexts>> filters = {
        {"pcf poisson 4", {{"filter", "pcf"}, {"pcf_kernel", "poisson"}, {"kernel_size", "4"}, {"filter_radius", "3"}}},
        {"pcss", {{"filter", "pcss"}, {"kernel_size", "4"}}},
    };
    for (const auto& [name, settings] : filters) {
        SettingTexts small_pages = settings;
        small_pages["page_size"] = "32";
        const Inspection in = inspect_scene(scene, {.method = "virtual", .settings = small_pages, .resolution = 2048});
        expect_many_pages(in);
        const VisibilityParity p = gpu_against_cpu_visibility(in, in.reference(kWidth, kHeight));
        ASSERT_GT(p.penumbra, 2000u) << name << ": the soft shadows are in view";
        EXPECT_LT(p.penumbra_mean_difference, 0.01) << name << ", in the penumbrae";
        std::cout << "virtual, 32-texel pages, " << name << ": mean |GPU - CPU| visibility " << p.mean_difference
                  << ", " << p.penumbra_mean_difference << " over the " << p.penumbra << " in a penumbra ("
                  << in.setup.maps.size() << " pages)\n";
    }
}

// What the pass refuses, each with one message: more levels than its uniforms hold, a table that does
// not match the setup's maps; beyond pages, more maps than the arrays hold, as before.
TEST(ShadowMapPassPages, RefusesWhatItCannotHold) {
    vtkNew<ShadowMapPass> pass;
    ShadowSetup setup;
    setup.selection.rule = MapSelection::Rule::pages;
    PageTable& table = setup.selection.pages;
    table.pages_per_side = 2;
    table.page_size = 8;
    table.levels.resize(ShadowMapPass::kMaxPageLevels);
    table.resident.assign(table.levels.size() * 4, -1);
    for (int i = 0; i < 12; ++i) {  // 12 pages: more than kMaxMaps
        table.resident[i] = i;
        table.pages.push_back({.level = i / 4, .page = {i % 2, (i / 2) % 2}});
        setup.maps.push_back({.viewport = glm::dvec4(i * 8, 0, i * 8 + 8, 8) / 128.0});
    }
    EXPECT_NO_THROW(pass->SetSetup(setup, 128));
    ShadowSetup deeper = setup;
    deeper.selection.pages.levels.emplace_back();
    deeper.selection.pages.resident.resize(deeper.selection.pages.resident.size() + 4, -1);
    EXPECT_THROW(pass->SetSetup(deeper, 128), std::invalid_argument);
    ShadowSetup mismatched = setup;
    mismatched.maps.pop_back();
    EXPECT_THROW(pass->SetSetup(mismatched, 128), std::invalid_argument);
    ShadowSetup paraboloid = setup;
    paraboloid.maps[3].projection = Projection::paraboloid;
    EXPECT_THROW(pass->SetSetup(paraboloid, 128), std::invalid_argument);
    ShadowSetup tiles = setup;
    tiles.selection.rule = MapSelection::Rule::tile_bounds;
    EXPECT_THROW(pass->SetSetup(tiles, 128), std::invalid_argument);
}
