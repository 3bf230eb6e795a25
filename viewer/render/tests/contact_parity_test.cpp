// Contact shadows on the GPU (issue 28): the pass's camera depth image and its march
// (render/contact_depth_image.hpp, glsl/contact_shadow.glsl) against the CPU's march in the
// reference's visible points (receiver_visibility), pixel for pixel, on the planted scene whose
// shadows a large normal offset lifts off their casters.
#include <cmath>
#include <iostream>
#include <gtest/gtest.h>

#include "metrics/shadow_error.hpp"
#include "view_test_support.hpp"
#include "views/view.hpp"
#include "visibility_parity.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kWidth = 480, kHeight = 270;

struct ContactParity {
    size_t compared = 0;
    size_t darkened = 0;   // pixels the map lights and the CPU's contact shadow darkens
    size_t agreeing = 0;   // of those, the pixels the GPU darkens too
    size_t differing = 0;  // compared pixels whose verdicts (visibility below ½) differ
};

ContactParity gpu_against_cpu_contact(const Scene& scene, const std::map<std::string, std::string>& settings) {
    const Inspection in = inspect_scene(scene, {.method = "focused", .settings = settings, .resolution = 1024});
    const ReferenceImage ref = exact_reference(scene, tessellate(scene), kWidth, kHeight);
    const RgbImage gpu = gpu_visibility(in, kWidth, kHeight);
    const ShadowReader reader(in.setup, in.depth(), in.scene.light, in.lookup);
    const std::vector<float> cpu = receiver_visibility(scene, ref, reader);
    ContactParity parity;
    for (int y = 1; y < kHeight - 1; ++y)
        for (int x = 1; x < kWidth - 1; ++x) {
            const size_t i = static_cast<size_t>(y) * kWidth + x;
            if (cpu[i] < 0.0f || !inside_one_face(ref, x, y)) continue;
            const bool gpu_shadowed = gpu.at(x, y)[0] < 128, cpu_shadowed = cpu[i] < 0.5f;
            ++parity.compared;
            parity.differing += gpu_shadowed != cpu_shadowed;
            const bool map_lights = reader.visibility({.position = ref.position[i], .normal = ref.normal[i]}) >= 0.5;
            if (map_lights && cpu_shadowed) {
                ++parity.darkened;
                parity.agreeing += gpu_shadowed;
            }
        }
    return parity;
}

}  // namespace

// The contact shadows restore thousands of pixels of the lifted shadows, and the GPU darkens the
// same pixels: the verdicts differ on a few pixels in a thousand at most (a sample whose surface
// is an edge pixel's, where the rasterizer's depth and the traced point's part).
TEST(ContactShadowPass, GpuAgreesWithCpu) {
    const Scene scene = shipped_scene("planks_on_plane", kWidth, kHeight);
    for (const auto& [name, settings] : std::vector<std::pair<std::string, std::map<std::string, std::string>>>{
             {"hard", {{"bias_normal", "8"}, {"contact_length", "1"}}},
             {"pcf, 16 steps",
              {{"bias_normal", "8"},
               {"filter", "pcf"},
               {"contact_length", "0.5"},
               {"contact_steps", "16"},
               {"contact_thickness", "0.2"}}}}) {
        const ContactParity p = gpu_against_cpu_contact(scene, settings);
        std::cout << name << ": " << p.darkened << " pixels darkened by contact shadows, " << p.agreeing
                  << " of them on the GPU too; verdicts differ on " << p.differing << " of " << p.compared
                  << " pixels\n";
        ASSERT_GT(p.compared, kWidth * kHeight / 4u) << name;
        EXPECT_GT(p.darkened, 500u) << name << ": the contact shadows restore the lifted shadows";
        EXPECT_GT(p.agreeing, 0.98 * p.darkened) << name;
        EXPECT_LT(p.differing, p.compared / 200) << name;
    }
}

// Through an alpha-tested fence: the camera depth image the GPU marches in has the fence's holes, as
// the CPU's (the reference's rays pass them) and the shaded image do; an image with the fence drawn
// whole would hide the ground seen through the holes behind bars a thickness in front of it.
TEST(ContactShadowPass, GpuAgreesWithCpuThroughAnAlphaTestedFence) {
    Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/fence.gltf");
    scene.camera.aspect = static_cast<double>(kWidth) / kHeight;
    const ContactParity p =
        gpu_against_cpu_contact(scene, {{"contact_length", "1"}, {"contact_steps", "16"}, {"contact_thickness", "2"}});
    std::cout << "fence: " << p.darkened << " pixels darkened by contact shadows, " << p.agreeing
              << " of them on the GPU too; verdicts differ on " << p.differing << " of " << p.compared << " pixels\n";
    ASSERT_GT(p.compared, kWidth * kHeight / 8u);
    EXPECT_GT(p.darkened, 100u) << "the contact shadows darken the ground behind the bars";
    EXPECT_GT(p.agreeing, 0.98 * p.darkened);
    EXPECT_LT(p.differing, p.compared / 200);
}
