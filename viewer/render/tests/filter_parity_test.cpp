// The GPU pass reads shadows as the one CPU lookup does (issue 15): for each filter and each depth
// bias, and each depth format (issue 26), the pass's visibility per pixel
// (ShadowMapPass::Output::visibility, a grey level) against ShadowReader::visibility of the same
// receiver: the visible point, its normal, the Poisson disk's turn at that pixel.
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>
#include <gtest/gtest.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include "lookup/kernel_taps.hpp"
#include "lookup/shadow_reader.hpp"
#include "render/shadow_map_pass.hpp"
#include "render/x_display.hpp"
#include "view_test_support.hpp"
#include "views/view.hpp"

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

// The Camera view drawn as render_view draws it, its pass switched to the visibility output.
RgbImage gpu_visibility(const Inspection& in) {
    const XDisplay x("the filter parity test");
    vtkNew<vtkRenderWindow> window;
    window->SetInteractor(nullptr);
    window->SetDisplayId(x.handle());
    window->SetOffScreenRendering(1);
    window->SetMultiSamples(0);
    window->SetSize(kWidth, kHeight);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    build_view(renderer, in, view_or_throw("camera"),
               ViewOptions{.lit_mask = true, .width = kWidth, .height = kHeight});
    ShadowMapPass::SafeDownCast(renderer->GetPass())->SetOutput(ShadowMapPass::Output::visibility);
    window->Render();
    RgbImage image = grab(window);
    window->Finalize();
    return image;
}

// A pixel whose 3x3 neighbourhood sees one face of one object: no object edge or box corner inside.
bool inside_one_face(const ReferenceImage& ref, int x, int y) {
    const size_t i = static_cast<size_t>(y) * ref.width + x;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const size_t j = i + dy * ref.width + dx;
            if (!ref.visible[j] || ref.object[j] != ref.object[i] || ref.normal[j] != ref.normal[i]) return false;
        }
    return true;
}

// |GPU − CPU| visibility over the pixels compared, and over those in a penumbra alone: most pixels
// are fully lit or fully shadowed, so that a GPU filtering nothing would still differ little on average.
struct Parity {
    size_t compared = 0;
    size_t penumbra = 0;  // pixels the CPU sees partly lit (visibility in (0.05, 0.95))
    size_t shadowed = 0;  // pixels the CPU sees less than half lit
    double mean_difference = 0.0, penumbra_mean_difference = 0.0;
};

Parity gpu_against_cpu_visibility(const Inspection& in, const ReferenceImage& ref) {
    const RgbImage gpu = gpu_visibility(in);
    const ShadowReader reader(in.setup, in.depth(), in.scene.light, in.lookup);
    Parity parity;
    double sum = 0.0, penumbra_sum = 0.0;
    for (int y = 1; y < kHeight - 1; ++y)
        for (int x = 1; x < kWidth - 1; ++x) {
            if (!inside_one_face(ref, x, y)) continue;
            const size_t i = static_cast<size_t>(y) * kWidth + x;
            const double cpu = reader.visibility(
                {.position = ref.position[i], .normal = ref.normal[i], .rotation = pixel_rotation(x, y)});
            const double difference = std::abs(gpu.at(x, y)[0] / 255.0 - cpu);
            const bool penumbra = cpu > 0.05 && cpu < 0.95;
            sum += difference;
            penumbra_sum += penumbra ? difference : 0.0;
            ++parity.compared;
            parity.penumbra += penumbra;
            parity.shadowed += cpu < 0.5;
        }
    parity.mean_difference = parity.compared ? sum / parity.compared : 0.0;
    parity.penumbra_mean_difference = parity.penumbra ? penumbra_sum / parity.penumbra : 0.0;
    return parity;
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
            const Parity p = gpu_against_cpu_visibility(inspect_scene(scene, request), ref);
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
