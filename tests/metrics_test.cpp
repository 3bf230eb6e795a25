// The error metrics against closed forms: Lloyd's m for a uniform map under an overhead light, its
// perspective and projection factors, and misclassification shares on a scene where the answer is
// known.
#include <gtest/gtest.h>

#include "registry/method.hpp"
#include "metrics/measurement.hpp"
#include "metrics/shadow_error.hpp"
#include "scene/scene_loader.hpp"
#include "scene/tessellation.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using shadowlab::testing::camera_20_units_above_the_origin;
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
    scene.camera = camera_20_units_above_the_origin();
    return scene;
}

ShadowError measure(const Scene& scene, const std::string& method, int resolution, int pixels) {
    const Method& m = *find_method(method);
    const ShadowSetup setup = m.compute_maps(gather_inputs(scene), resolve_settings(method, m.settings, {}), nullptr);
    const WorldTriangles triangles = tessellate(scene);
    const ReferenceImage reference = exact_reference(scene, triangles, pixels, pixels);
    const DepthMap depth = rasterize_depth(triangles, caster_flags(scene), setup, resolution);
    const ShadowReader reader(setup, depth, scene.light, {.bias = {.constant = 0.05, .slope_scale = 0.0}});
    return measure_shadow_error(scene, reference, reader, receiver_visibility(scene, reference, reader));
}

// A 100 x 20 ground (long along x) under a camera 20 units up looking straight down, lit from
// `tilt_deg` off the vertical in the x-y plane: the plane of the image's middle row.
Scene ground_under_camera(double tilt_deg) {
    Scene scene = overhead_scene();
    scene.objects.resize(1);
    scene.objects[0].size = {100, 1, 20};
    const double tilt = glm::radians(tilt_deg);
    scene.light.direction = {std::sin(tilt), -std::cos(tilt), 0};
    return scene;
}

// A camera looking horizontally along a 5000 x 5000 ground, lit from straight above (γ = 90°),
// with near n = 1 and far f = 1000. Its eye is n tan(fov/2) up, so the ground's nearest point in
// view lies on the near plane, at the image's bottom edge. A post gives the maps a caster.
constexpr double kNear = 1, kFar = 1000;

Scene horizon_scene() {
    Scene scene = overhead_scene();
    scene.objects[0].size = {5000, 1, 5000};
    scene.objects[1].size = {2, 4, 2};
    scene.objects[1].position = {30, 2, 400};
    scene.objects[1].receives = false;  // only the ground is judged
    const double height = kNear * std::tan(glm::radians(30.0));
    scene.camera.position = {0, height, 0};
    scene.camera.target = {0, height, 1};
    scene.camera.up = {0, 1, 0};
    scene.camera.near = kNear;
    scene.camera.far = kFar;
    return scene;
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
    EXPECT_NEAR(high.m_perspective.mean / low.m_perspective.mean, 0.5, 0.05);
    EXPECT_NEAR(high.m_perspective.max / low.m_perspective.max, 0.5, 0.05);
    // The projection factor is the surface's: the resolution does not change it.
    EXPECT_NEAR(high.m_projection.mean / low.m_projection.mean, 1.0, 1e-3);
    EXPECT_NEAR(high.m_projection.max / low.m_projection.max, 1.0, 1e-3);
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

// The depth step `measure` reports is one step of the map's depth format (the depth_format setting)
// in world units along the light: an N-bit unorm's 1 / (2^N − 1) of the map's depth range at every
// pixel, so that unorm16's is 256 times unorm24's; float32's is its spacing at each pixel's depth,
// at most 2^-24 of the range (on the ground, at the far end), far less on the box's top near d = 0.
TEST(Metrics, DepthStepOfAnOrthographicMapIsItsDepthRangeOverTheFormatsLevels) {
    const Scene scene = overhead_scene();
    const Method& uniform = *find_method("uniform");
    const ShadowMap map =
        uniform.compute_maps(gather_inputs(scene), resolve_settings("uniform", {}, {}), nullptr).maps[0];
    // The uniform map's depth spans the scene's height (the box: 4 units) over [0, 1].
    EXPECT_NEAR(world_per_depth_unit(map, scene.light.direction, {10, 0, 10}), 4.0, 1e-9);
    const MeasureContext context = prepare_measurement(scene, 81, 81);
    const auto depth_step_in = [&](const std::string& format) {
        const Settings settings = resolve_settings("uniform", uniform.settings, {{"depth_format", format}});
        return shadowlab::measure(context, uniform, settings, 256, 0.05).error.depth_step;
    };
    const AliasingStats unorm16 = depth_step_in("unorm16"), unorm24 = depth_step_in("unorm24"),
                        float32 = depth_step_in("float32");
    EXPECT_NEAR(unorm24.mean, 4.0 / 16777215.0, 1e-15);
    EXPECT_NEAR(unorm24.max, 4.0 / 16777215.0, 1e-15);
    EXPECT_NEAR(unorm16.mean, 4.0 / 65535.0, 1e-12);
    EXPECT_NEAR(unorm16.mean / unorm24.mean, 256.0, 0.01);
    EXPECT_NEAR(float32.max, 4.0 / 16777216.0, 1e-15);
    EXPECT_LT(float32.mean, 0.99 * float32.max) << "the box's top, near d = 0, is finer";
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
    const ShadowMap map =
        uniform.compute_maps(gather_inputs(scene), resolve_settings("uniform", {}, {}), nullptr).maps[0];
    // A 100-unit map of 500 texels: 0.2 units a texel; the ground faces the light (θ = 0).
    EXPECT_NEAR(slope_scaled_bias(map, 500, scene.light.direction, {10, 0, 10}, 1.0), 0.2, 1e-6);
    // A face at 45° to the light needs twice that.
    EXPECT_NEAR(slope_scaled_bias(map, 500, scene.light.direction, {10, 0, 10}, std::sqrt(0.5)), 0.4, 1e-6);
}

TEST(Metrics, ProjectionFactorIsLloydsCosineRatioInHisPlane) {
    // Along the image's middle row the ground's normal, the light and the view ray lie in one plane
    // (Lloyd et al. 2006), and the uniform map's texel is longest in it: 100 units of ground
    // against 20 across. The projection factor is then cos φ_eye / cos φ_light, φ_eye from the
    // vertical to the pixel's ray (cos = height / distance), φ_light the light's tilt; within the
    // one-pixel differences' own error (a pixel's angle times the tangent of the halfway plane's
    // tilt: 0.3 % at 60°). At the centre pixel under a light from straight above the ground faces
    // both the eye and the light: 1.
    const int pixels = 201, middle = pixels / 2;
    for (double tilt_deg : {0.0, 60.0}) {
        const Scene scene = ground_under_camera(tilt_deg);
        const ShadowError e = measure(scene, "uniform", 512, pixels);
        const double cos_light = std::cos(glm::radians(tilt_deg));
        for (int x = 5; x < pixels - 5; x += 15) {
            const size_t i = size_t(middle) * pixels + x;
            // The ground point this pixel sees, from the image plane at distance 1 (fov 60°).
            const double across = std::tan(glm::radians(30.0)) * (2.0 * (x + 0.5) / pixels - 1.0);
            const double cos_eye = 1.0 / std::sqrt(1.0 + across * across);
            EXPECT_NEAR(e.m_projection_image[i], cos_eye / cos_light, 0.005 * cos_eye / cos_light)
                << "tilt " << tilt_deg << "°, pixel " << x;
            EXPECT_NEAR(e.m_perspective_image[i] * e.m_projection_image[i], e.m_image[i], 1e-5 * e.m_image[i]);
        }
    }
    const ShadowError overhead = measure(ground_under_camera(0.0), "uniform", 512, pixels);
    EXPECT_NEAR(overhead.m_projection_image[size_t(middle) * pixels + middle], 1.0, 1e-6);
}

TEST(Metrics, LiSPSMCutsTheMaxPerspectiveFactorBySqrtFarOverNear) {
    // Derivation for horizon_scene, in light space (x across the view, y along it from the eye; a
    // texel is 1/N of u and of v; at depth z a pixel spans 2 z tan 30° / H across its ray, H the
    // image's rows). The intersection body is the frustum's slice of the ground: |x| <= z tan 30°,
    // y from n to f. The focused map fits it orthographically: its texel is 2 f tan 30° / N wide
    // at every depth. LiSPSM (Wimmer et al. 2004; lispsm.cpp, with z_f = f at γ = 90°) puts its
    // centre C at n_opt = n + sqrt(n f) before the body and stores u ∝ x / y_c, y_c = y - n + n_opt;
    // u spans the widest x / y_c, f tan 30° / (f + sqrt(n f)), so its texel is
    // 2 f tan 30° y_c / ((f + sqrt(n f)) N) wide. Against the pixel (∝ z) both widths are largest
    // at the nearest ground in view, z_min. Along the view, LiSPSM's texel, (f - n) y_c² /
    // ((f + sqrt(n f)) n_opt N), stands to its width at z_min as the focused map's (f - n) / N
    // stands to its own, (f - n) / (2 f tan 30°) ≈ 0.87, and against the pixel it is no larger at
    // the far end than at z_min (n_opt makes the two equal). So both maxima lie at z_min, on texels
    // of one shape, and their ratio is that of the widths:
    //     focused / LiSPSM = (f + sqrt(n f)) / (z_min - n + n_opt) = (f + sqrt(n f)) / (z_min + sqrt(n f)),
    // sqrt(f/n) at z_min = n: the gain over a frustum-fit map that Wimmer et al. (2004) and Lloyd et
    // al. (2006) derive for n_opt with the light perpendicular to the view. The eye is n tan 30°
    // above the ground, so the bottom row sees z_min = n H / (H - 1). Off the middle column LiSPSM's
    // lines of equal u fan out from C (by up to atan(tan 30° / n_opt) ≈ 1°), which moves the
    // measured ratio by under 1 % (31.85 measured against 31.62).
    const int pixels = 128, n = 1024;
    const Scene scene = horizon_scene();
    const double z_min = kNear * pixels / (pixels - 1.0);
    const double expected = (kFar + std::sqrt(kNear * kFar)) / (z_min + std::sqrt(kNear * kFar));
    EXPECT_NEAR(expected, std::sqrt(kFar / kNear), 0.01 * std::sqrt(kFar / kNear));
    const ShadowError focused = measure(scene, "focused", n, pixels), lispsm = measure(scene, "lispsm", n, pixels);
    EXPECT_NEAR(focused.m_perspective.max / lispsm.m_perspective.max, expected, 0.05 * expected);
}
