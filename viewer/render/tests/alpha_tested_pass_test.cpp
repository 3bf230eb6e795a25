// Alpha-tested casters on the GPU: stage 1 discards the fragments of a caster's texture below its
// cutoff, as the CPU rasterizer leaves those texels, and stage 2 the surfaces' fragments, as the
// reference's camera rays pass through the holes. The fence scene (data/scenes/fence.gltf) under a sun,
// a spot and a point light (the paraboloids' casters split, and their pieces' texture coordinates with
// them), in every depth format.
#include <iostream>
#include <map>
#include <gtest/gtest.h>

#include "scene/scene_loader.hpp"
#include "view_test_support.hpp"
#include "views/offscreen_view.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kWidth = 480, kHeight = 270;

Scene fence() {
    Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/fence.gltf");
    scene.camera.aspect = static_cast<double>(kWidth) / kHeight;
    return scene;
}

// The fence under a light behind it and above: a spot aimed at its foot, or a point light.
Scene fence_under(LightType type) {
    Scene scene = fence();
    scene.light.type = type;
    scene.light.position = {0.8, 6.0, -5.0};
    scene.light.direction = glm::normalize(glm::dvec3(0.0, 0.5, 1.5) - scene.light.position);
    scene.light.cone_deg = 90.0;
    return scene;
}

using SettingTexts = std::map<std::string, std::string>;

void expect_agreement(const Scene& scene, const std::string& method, SettingTexts settings, const std::string& what) {
    for (const DepthFormat& format : depth_formats()) {
        settings.merge(depth_format_settings(format));
        const Inspection in = inspect_scene(scene, {.method = method, .settings = settings, .resolution = 2048});
        ASSERT_TRUE(in.triangles.alpha_tested());
        const Agreement a = gpu_against_cpu_lookup(in, kWidth, kHeight);
        ASSERT_EQ(a.undrawn, 0u) << "the GPU drew nothing where the reference sees something";
        ASSERT_GT(a.compared, kWidth * kHeight / 4u);
        EXPECT_GE(a.share(), 0.995) << what << ", " << describe(format) << ": " << a.compared - a.agreed << " of "
                                    << a.compared << " pixels differ";
        std::cout << what << ", " << describe(format) << ": GPU and CPU agree on " << a.agreed << " of " << a.compared
                  << " pixels away from edges\n";
    }
}

}  // namespace

TEST(GpuAgreesWithCpuOnAlphaTestedCasters, UnderTheSunASpotAndAPointLight) {
    expect_agreement(fence(), "focused", {}, "focused, sun");
    expect_agreement(fence_under(LightType::spot), "focused", {}, "focused, spot");
    expect_agreement(fence_under(LightType::point), "cube", {}, "cube, point light");
    expect_agreement(fence_under(LightType::point), "dpsm", {{"tessellate", "0.5"}},
                     "dpsm tessellate=0.5, point light");
}

// The agreement above is no accident of an opaque fence: the GPU's lit mask against the CPU's verdicts
// with the fence drawn opaque into the CPU's map differs on the holes' light.
TEST(GpuAgreesWithCpuOnAlphaTestedCasters, AndNotWithAnOpaqueFence) {
    const Inspection in = inspect_scene(fence(), {.method = "focused", .resolution = 2048});
    ViewOptions options;
    options.lit_mask = true;
    const RgbImage gpu = render_view(in, view_or_throw("camera"), options, kWidth, kHeight);
    const ReferenceImage& ref = in.reference(kWidth, kHeight);
    WorldTriangles opaque = in.triangles;
    opaque.alpha.clear();
    const DepthMap opaque_depth = rasterize_depth(opaque, in.casters, in.setup, in.resolution, in.lookup.format);
    const ShadowReader reader(in.setup, opaque_depth, in.scene.light, in.lookup);
    std::vector<int8_t> cpu(ref.visible.size(), -1);
    for (size_t i = 0; i < cpu.size(); ++i)
        if (ref.visible[i])
            cpu[i] = reader.visibility({.position = ref.position[i], .normal = ref.normal[i]}) < 0.5 ? 0 : 1;
    const Agreement a = agreement(gpu, cpu, ref);
    ASSERT_GT(a.compared, kWidth * kHeight / 4u);
    EXPECT_GT(a.compared - a.agreed, 500u) << "the holes' light, lit on the GPU, shadowed by an opaque fence";
    std::cout << "against an opaque fence the GPU differs on " << a.compared - a.agreed << " of " << a.compared
              << " pixels\n";
}
