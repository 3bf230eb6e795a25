// The error metrics against closed forms: Lloyd's m for a uniform map under an overhead light,
// and misclassification shares on a scene where the answer is known.
#include <gtest/gtest.h>

#include "registry/method.hpp"
#include "metrics/measurement.hpp"
#include "metrics/shadow_error.hpp"
#include "scene/scene_loader.hpp"
#include "scene/tessellation.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using shadowlab::testing::source_path;

namespace {

// A 100 x 100 ground and a 4-unit box, light straight down, camera 20 units up looking straight down.
Scene overhead_scene() {
    Scene scene;
    SceneObject ground;
    ground.shape = Shape::plane;
    ground.size = {100, 1, 100};
    ground.casts = false;
    SceneObject box;
    box.size = {4, 4, 4};
    box.position = {0, 2, 0};
    scene.objects = {ground, box};
    scene.light.direction = {0, -1, 0};
    scene.camera.position = {0, 20, 0};
    scene.camera.target = {0, 0, 0};
    scene.camera.up = {0, 0, -1};
    scene.camera.fov_y_deg = 60;
    scene.camera.aspect = 1;
    scene.camera.near = 1;
    scene.camera.far = 100;
    return scene;
}

ShadowError measure(const Scene& scene, const std::string& method, int resolution, int pixels) {
    const Method& m = *find_method(method);
    const ShadowSetup setup = m.compute_maps(gather_inputs(scene), resolve_settings(method, m.settings, {}), nullptr);
    const WorldTriangles triangles = tessellate(scene);
    const ReferenceImage reference = exact_reference(scene, triangles, pixels, pixels);
    const DepthMap depth = rasterize_depth(triangles, caster_flags(scene), setup, resolution);
    return measure_shadow_error(scene, reference, depth, setup, 0.05);
}

}  // namespace

TEST(Metrics, TexelExtentOfAnIsotropicJacobian) {
    // uv moves 1/1000 per pixel in both directions: a texel of a 500 map spans 2 pixels.
    EXPECT_NEAR(texel_extent_in_pixels({0.5, 0.5}, {0.501, 0.5}, {0.5, 0.501}, 500), 2.0, 1e-9);
    // Stretched: the longest extent counts.
    EXPECT_NEAR(texel_extent_in_pixels({0.5, 0.5}, {0.502, 0.5}, {0.5, 0.5005}, 500), 4.0, 1e-9);
}

TEST(Metrics, UniformMapUnderOverheadLightMatchesTheClosedForm) {
    const Scene scene = overhead_scene();
    const int n = 512, pixels = 201;
    const ShadowError e = measure(scene, "uniform", n, pixels);
    // Ground texel: 100 / n units; ground pixel under the camera: 2 h tan(fov / 2) / pixels.
    const double closed_form = (100.0 / n) / (2 * 20 * std::tan(glm::radians(30.0)) / pixels);
    // The ground is parallel to the image plane, so m is the same at every ground pixel; the image
    // centre sees the box top (4 units nearer), so take the ground beside it.
    for (int x : {pixels / 2 + 40, pixels / 2 + 80, 10})
        EXPECT_NEAR(e.m_image[size_t(pixels / 2) * pixels + x], closed_form, 0.01 * closed_form) << "pixel " << x;
    EXPECT_NEAR(e.m.max, closed_form * (20.0 / 16.0), 0.01 * closed_form * 1.25) << "the box top is 16 units away";
}

TEST(Metrics, DoublingTheResolutionHalvesM) {
    const Scene scene = overhead_scene();
    const ShadowError low = measure(scene, "uniform", 256, 161), high = measure(scene, "uniform", 512, 161);
    EXPECT_NEAR(high.m.mean / low.m.mean, 0.5, 0.05);
    EXPECT_NEAR(high.m.max / low.m.max, 0.5, 0.05);
}

TEST(Metrics, MisclassificationIsSmallAndSplitByKind) {
    Scene scene = overhead_scene();
    scene.light.direction = glm::normalize(glm::dvec3(0.4, -1, 0.3));  // the shadow shows beside the box
    const ShadowError fine = measure(scene, "focused", 1024, 161);
    EXPECT_GT(fine.receiver_pixels, 161u * 161u / 2);
    EXPECT_LT(fine.misclassified, 0.01);
    EXPECT_DOUBLE_EQ(fine.misclassified, fine.false_shadow + fine.false_light);
    // A 16-texel map over 100 units cannot draw a 4-unit box's shadow: the shadow leaks light.
    const ShadowError coarse = measure(scene, "uniform", 16, 161);
    EXPECT_GT(coarse.misclassified, 5 * fine.misclassified + 0.005);
    EXPECT_GT(coarse.false_light, coarse.false_shadow);
}

TEST(Metrics, DepthStepOfAnOrthographicMapIsItsDepthRangeOver2To24) {
    const Scene scene = overhead_scene();
    const Method& uniform = *find_method("uniform");
    const ShadowMap map = uniform.compute_maps(gather_inputs(scene), resolve_settings("uniform", {}, {}), nullptr).maps[0];
    // The uniform map's depth spans the scene's height (the box: 4 units) over [0, 1].
    EXPECT_NEAR(world_per_depth_unit(map, scene.light.direction, {10, 0, 10}), 4.0, 1e-9);
    const ShadowError e = measure(scene, "uniform", 256, 81);
    EXPECT_NEAR(e.depth_step.mean, 4.0 / 16777216.0, 1e-15);
}

TEST(Metrics, MethodsRankAsTheLiteratureSaysUnderAnOverheadLight) {
    // Only the ground receives, so that m measures perspective aliasing on it (walls edge-on to the
    // light would add projection aliasing). Uniform is worse than focused, focused worse than the
    // warps, in max m.
    Scene scene = shadowlab::load_scene(source_path("data/scenes/light_overhead.json"));
    for (SceneObject& o : scene.objects) o.receives = o.shape == Shape::plane;
    const MeasureContext context = prepare_measurement(scene, 480, 270);
    auto max_m = [&](const std::string& name) {
        const Method& m = *find_method(name);
        return shadowlab::measure(context, m, resolve_settings(name, m.settings, {}), 1024, -1.0).error.m.max;
    };
    const double uniform = max_m("uniform"), focused = max_m("focused");
    EXPECT_GT(uniform, focused);
    EXPECT_GT(focused, 2.0 * max_m("lispsm"));
    EXPECT_GT(focused, 2.0 * max_m("xpsm"));
}

TEST(Metrics, SlopeScaledBiasIsTheTexelSizeTimesOnePlusTanTheta) {
    const Scene scene = overhead_scene();
    const Method& uniform = *find_method("uniform");
    const ShadowMap map = uniform.compute_maps(gather_inputs(scene), resolve_settings("uniform", {}, {}), nullptr).maps[0];
    // A 100-unit map of 500 texels: 0.2 units a texel; the ground faces the light (θ = 0).
    EXPECT_NEAR(slope_scaled_bias(map, 500, scene.light.direction, {10, 0, 10}, 1.0), 0.2, 1e-6);
    // A face at 45° to the light needs twice that.
    EXPECT_NEAR(slope_scaled_bias(map, 500, scene.light.direction, {10, 0, 10}, std::sqrt(0.5)), 0.4, 1e-6);
}
