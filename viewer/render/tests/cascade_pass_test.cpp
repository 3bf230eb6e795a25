// Two maps chosen by view depth on the GPU: the blend band crossfaded as the CPU crossfades it
// (ShadowReader::visibility), and the Camera view's overlay painting each surface by the map serving it.
#include <array>
#include <iostream>
#include <gtest/gtest.h>

#include "methods/uniform.hpp"
#include "metrics/shadow_error.hpp"
#include "registry/method.hpp"
#include "view_test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kWidth = 960, kHeight = 540;  // pixels finer than the far map's texels, so that its strips show
constexpr double kBlendBand = 0.3;

// The floating box flattened into a wide slab turned 30° about y: a shadow 6 units across around the
// camera's target, its edges slanting across both maps' texels.
Scene slab_over_ground() {
    Scene scene = floating_box(kWidth, kHeight);
    scene.objects.at(1).size = {6.0, 0.5, 6.0};
    scene.objects.at(1).rotation_deg = {0.0, 30.0, 0.0};
    return scene;
}

// The uniform map twice, split by view depth 2 units beyond the camera's target, in the far half of
// the slab's shadow. The far map has a quarter of the near one's texels per side and looks along a
// light tilted toward x (it sees the scene sheared, x + 0.2 y): it puts the slab's shadow 0.6 units
// aside, so that inside the band the crossfade decides a strip along the shadow's edges.
ShadowSetup near_then_far(const ShadowInputs& inputs, const Settings& settings, Trace* trace) {
    const ShadowSetup uniform = compute_uniform(inputs, settings, trace);
    ShadowSetup setup{.maps = {uniform.maps.at(0), uniform.maps.at(0)}, .fallbacks = uniform.fallbacks};
    setup.maps[0].viewport = {0.0, 0.0, 0.5, 0.5};
    setup.maps[1].viewport = {0.5, 0.5, 0.625, 0.625};
    glm::dmat4 sheared(1.0);
    sheared[1][0] = 0.2;  // x += 0.2 y
    setup.maps[1].world_to_uvz = setup.maps[1].world_to_uvz * sheared;
    const Camera& camera = inputs.camera;
    setup.selection = {.rule = MapSelection::Rule::view_depth,
                       .eye = camera.position,
                       .view_axis = camera.view_direction(),
                       .split_depths = {0.0, glm::length(camera.target - camera.position) + 2.0, camera.far},
                       .blend_band = kBlendBand};
    return setup;
}

// The same without a band: a hard seam.
ShadowSetup near_then_far_hard(const ShadowInputs& inputs, const Settings& settings, Trace* trace) {
    ShadowSetup setup = near_then_far(inputs, settings, trace);
    setup.selection.blend_band = 0.0;
    return setup;
}

class TwoMapsByViewDepth : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        for (auto [name, compute] : {std::pair<const char*, ComputeMaps>{"near_then_far", near_then_far},
                                     std::pair<const char*, ComputeMaps>{"near_then_far_hard", near_then_far_hard}})
            if (!find_method(name))
                register_method({.name = name, .title = name, .description = "a test's own", .compute_maps = compute});
    }
};

// Whether a colour lies nearer to palette colour `mine` than to `other` (colours 0..1).
bool nearer(const unsigned char* c, const glm::vec3& mine, const glm::vec3& other) {
    const glm::vec3 colour = glm::vec3(c[0], c[1], c[2]) / 255.0f;
    return glm::length(colour - mine) < glm::length(colour - other);
}

}  // namespace

// The GPU's verdicts against the CPU visibility's threshold on every visible pixel away from edges, and
// on those alone where the band decides (the crossfade's verdict is not the own map's): there a GPU
// ignoring the band would be wrong on every pixel.
TEST_F(TwoMapsByViewDepth, GpuBlendsAsTheCpuDoes) {
    const Scene scene = slab_over_ground();
    for (int resolution : {256, 1024}) {
        const Inspection in = inspect(scene, "near_then_far", resolution);
        ShadowSetup own_map_only = in.setup;
        own_map_only.selection.blend_band = 0.0;
        const ReferenceImage& ref = in.reference(kWidth, kHeight);
        const ShadowReader blended(in.setup, in.depth(), in.scene.light, in.lookup);
        const ShadowReader own_map(own_map_only, in.depth(), in.scene.light, in.lookup);
        std::vector<int8_t> cpu(ref.visible.size(), -1), decided_by_band(ref.visible.size(), -1);
        for (size_t i = 0; i < cpu.size(); ++i) {
            if (!ref.visible[i]) continue;
            const Receiver receiver{.position = ref.position[i], .normal = ref.normal[i]};
            cpu[i] = blended.visibility(receiver) < 0.5 ? 0 : 1;
            if ((cpu[i] == 0) != (own_map.visibility(receiver) < 0.5)) decided_by_band[i] = cpu[i];
        }
        ViewOptions options;
        options.lit_mask = true;
        const RgbImage gpu = render_view(in, view_or_throw("camera"), options, kWidth, kHeight);
        const Agreement all = agreement(gpu, cpu, ref), band = agreement(gpu, decided_by_band, ref);
        ASSERT_EQ(all.undrawn, 0u);
        ASSERT_GT(all.compared, kWidth * kHeight / 4u);
        EXPECT_GE(all.share(), 0.995) << resolution << ": " << all.compared - all.agreed << " of " << all.compared
                                      << " pixels differ";
        ASSERT_GT(band.compared, 500u) << "the band decides a strip along the shadow's edges";
        EXPECT_GE(band.share(), 0.99) << resolution << ": " << band.compared - band.agreed << " of " << band.compared
                                      << " pixels the band decides differ";
        RecordProperty("blend_agreement_" + std::to_string(resolution), std::to_string(all.share()));
        std::cout << "blend band " << kBlendBand << " at " << resolution << ": GPU and CPU agree on " << all.agreed
                  << " of " << all.compared << " pixels away from edges, on " << band.agreed << " of " << band.compared
                  << " the band decides\n";
    }
}

// Seed 003's "shadows per split": the ground before the split depth in map 0's colour, beyond it
// in map 1's.
TEST_F(TwoMapsByViewDepth, CascadeOverlayPaintsEachSplitInItsMapsColour) {
    const Scene scene = slab_over_ground();
    const Inspection in = inspect(scene, "near_then_far_hard", 1024);
    ViewOptions options;
    options.overlay = MapOverlay::cascade_index;
    const RgbImage image = render_view(in, view_or_throw("camera"), options, kWidth, kHeight);
    const ReferenceImage& ref = in.reference(kWidth, kHeight);
    const MapSelection& s = in.setup.selection;
    const double split = s.split_depths[1], margin = 0.05 * split;
    std::array<size_t, 2> pixels{}, in_own_colour{};
    for (int y = 60; y < kHeight - 40; ++y)  // below the legend, above the caption
        for (int x = 0; x < kWidth; ++x) {
            const size_t i = static_cast<size_t>(y) * kWidth + x;
            if (!ref.visible[i]) continue;
            const double depth = glm::dot(ref.position[i] - s.eye, s.view_axis);
            if (std::abs(depth - split) < margin) continue;
            const int map = depth < split ? 0 : 1;
            ++pixels[map];
            in_own_colour[map] += nearer(image.at(x, y), kMapPalette[map], kMapPalette[1 - map]);
        }
    for (int map : {0, 1}) {
        ASSERT_GT(pixels[map], 2000u) << "map " << map << " serves some of the view";
        EXPECT_GE(in_own_colour[map], 0.98 * pixels[map])
            << "map " << map << ": " << in_own_colour[map] << " of " << pixels[map] << " pixels in its colour";
    }
}
