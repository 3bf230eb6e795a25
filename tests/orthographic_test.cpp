// Orthographic cameras (issue 24): the camera's box, its parallel primary rays, and the methods on an
// orthographic top-down view of the shipped town: the maps hold every visible receiver, they judge it
// about as well as the focused map does, and a warp that has nothing to do under parallel view rays
// says so by name.
#include <gtest/gtest.h>

#include <cmath>

#include "metrics/measurement.hpp"
#include "reference/camera_rays.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kWidth = 192, kHeight = 120, kResolution = 1024;

// Looking straight down at the middle of the town, 60 units from the image's centre to its top.
Camera top_down() {
    return {.position = {10.0, 120.0, 5.0},
            .target = {10.0, 0.0, 5.0},
            .up = {0.0, 0.0, -1.0},
            .aspect = double(kWidth) / kHeight,
            .near = 1.0,
            .far = 200.0,
            .projection = CameraProjection::orthographic,
            .half_height = 60.0};
}

Scene orthographic_town(LightType light = LightType::directional) {
    Scene scene = load_scene(source_path("data/scenes/default.json"));
    scene.camera = top_down();
    if (light != LightType::directional) {
        scene.light.type = light;
        scene.light.position = {40.0, 90.0, 30.0};
        scene.light.direction = glm::normalize(glm::dvec3(-0.3, -1.0, -0.2));
        scene.light.cone_deg = 120.0;
    }
    return scene;
}

ShadowSetup run(const Method& method, const ShadowInputs& inputs) {
    return method.compute_maps(inputs, resolve_settings(method.name, method.settings, {}), nullptr);
}

Measurement measured(const MeasureContext& context, const std::string& name) {
    const Method& m = method_or_throw(name);
    return measure(context, m, resolve_settings(name, m.settings, {}), kResolution, -1.0);
}

// The visible points of receiving objects in the reference.
std::vector<glm::dvec3> visible_receivers(const MeasureContext& context) {
    std::vector<glm::dvec3> points;
    const ReferenceImage& ref = context.reference;
    for (size_t i = 0; i < ref.visible.size(); ++i)
        if (ref.visible[i] && context.scene.objects[ref.object[i]].receives) points.push_back(ref.position[i]);
    return points;
}

double distance_to_line(const glm::dvec3& p, const EyeRay& ray) {
    return glm::length(glm::cross(p - ray.origin, glm::normalize(ray.direction)));
}

}  // namespace

TEST(OrthographicCamera, ItsFrustumIsTheBoxItsProjectionMapsOntoTheClipCube) {
    const Camera camera = top_down();
    const Frustum box = camera.frustum();
    const glm::dmat4 clip_from_world = camera.projection_matrix() * camera.view_matrix();
    for (const glm::dvec3& corner : box.corners) {
        const glm::dvec4 clip = clip_from_world * glm::dvec4(corner, 1.0);
        EXPECT_DOUBLE_EQ(clip.w, 1.0);
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(std::abs(clip[a]), 1.0, 1e-12) << "axis " << a;
    }
    // The near and far faces are the same rectangle, 2 half_height high and 2 aspect half_height wide.
    for (int i = 0; i < 4; ++i)
        EXPECT_NEAR(glm::length(box.corners[i + 4] - box.corners[i]), camera.far - camera.near, 1e-9);
    EXPECT_NEAR(glm::length(box.corners[3] - box.corners[0]), 2.0 * camera.half_height, 1e-9);
    EXPECT_NEAR(glm::length(box.corners[1] - box.corners[0]), 2.0 * camera.aspect * camera.half_height, 1e-9);
    const glm::dvec3 inside_edge = camera.position + glm::dvec3(0.99 * camera.aspect * camera.half_height, -100.0, 0.0);
    EXPECT_TRUE(box.contains(inside_edge));
    EXPECT_FALSE(box.contains(inside_edge + glm::dvec3(0.02 * camera.aspect * camera.half_height, 0.0, 0.0)));
}

TEST(OrthographicCamera, ItsPrimaryRaysAreParallelAndLandOnTheirPixels) {
    const Camera camera = top_down();
    const CameraRays rays(camera, kWidth, kHeight);
    const glm::dmat4 clip_from_world = camera.projection_matrix() * camera.view_matrix();
    for (int y = 0; y < kHeight; y += 7)
        for (int x = 0; x < kWidth; x += 5) {
            const EyeRay ray = rays.ray(x, y);
            EXPECT_LT(glm::length(ray.direction - camera.view_direction()), 1e-15) << x << ", " << y;
            const glm::dvec3 p = ray.origin + 50.0 * ray.direction;
            EXPECT_NEAR(rays.view_depth(p), 50.0, 1e-9);
            const glm::dvec2 pixel = rays.pixel_of_ndc(glm::dvec2(clip_from_world * glm::dvec4(p, 1.0)));
            EXPECT_NEAR(pixel.x, x, 1e-9);
            EXPECT_NEAR(pixel.y, y, 1e-9);
        }
}

TEST(OrthographicCamera, TheReferenceSeesAlongParallelRays) {
    const MeasureContext context = prepare_measurement(orthographic_town(), kWidth, kHeight);
    const ReferenceImage& ref = context.reference;
    const CameraRays rays(context.scene.camera, ref.width, ref.height);
    size_t seen = 0, lit = 0;
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) {
            const size_t i = size_t(y) * ref.width + x;
            if (!ref.visible[i]) continue;
            ++seen;
            lit += ref.lit[i];
            EXPECT_LT(distance_to_line(ref.position[i], rays.ray(x, y)), 1e-9) << x << ", " << y;
            // Seen from above: every normal turned up toward the camera, none edge-on.
            EXPECT_LT(glm::dot(ref.normal[i], context.scene.camera.view_direction()), 0.0) << x << ", " << y;
        }
    EXPECT_EQ(seen, ref.visible.size()) << "the ground fills the view";
    EXPECT_GT(lit, seen / 2) << "a sunny town";
    EXPECT_LT(lit, seen) << "with shadows";
}

class OrthographicTownMaps : public ::testing::TestWithParam<std::string> {};

TEST_P(OrthographicTownMaps, MapsHoldEveryVisibleReceiverAndJudgeItAsFocusedDoes) {
    const std::string& name = GetParam();
    const MeasureContext context = prepare_measurement(orthographic_town(), kWidth, kHeight);
    const ShadowSetup setup = run(method_or_throw(name), gather_inputs(context.scene));
    ASSERT_FALSE(setup.maps.empty());
    for (const ShadowMap& map : setup.maps) EXPECT_TRUE(finite(map.world_to_uvz)) << name;
    EXPECT_TRUE(are_fallbacks(setup.fallbacks)) << describe(setup.fallbacks);
    const std::vector<glm::dvec3> receivers = visible_receivers(context);
    ASSERT_FALSE(receivers.empty());
    for (const glm::dvec3& p : receivers) {
        const std::optional<glm::dvec3> uvz = setup_uvz(setup, p);
        ASSERT_TRUE(uvz && in_unit_cube(*uvz, 1e-6))
            << name << ": a visible receiver maps to (" << (uvz ? uvz->x : NAN) << ", " << (uvz ? uvz->y : NAN) << ", "
            << (uvz ? uvz->z : NAN) << ")";
    }
    const Measurement m = measured(context, name), focused = measured(context, "focused");
    ASSERT_GT(m.error.receiver_pixels, 0u);
    EXPECT_LE(m.error.misclassified, 2.0 * focused.error.misclassified + 0.01) << name;
    EXPECT_LT(m.error.misclassified, 0.05) << name;
    for (const AliasingStats& s : {m.error.m, m.error.m_perspective, m.error.m_projection}) {
        EXPECT_TRUE(std::isfinite(s.max) && std::isfinite(s.mean)) << name;
        EXPECT_GT(s.mean, 0.0) << name;
    }
}

INSTANTIATE_TEST_SUITE_P(Methods, OrthographicTownMaps, ::testing::Values("uniform", "focused", "lispsm", "cascades"));

// The maps of two setups are the same.
void expect_same_maps(const ShadowSetup& got, const ShadowSetup& expected, const std::string& what) {
    ASSERT_EQ(got.maps.size(), expected.maps.size()) << what;
    for (size_t k = 0; k < got.maps.size(); ++k)
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                EXPECT_DOUBLE_EQ(got.maps[k].world_to_uvz[c][r], expected.maps[k].world_to_uvz[c][r]) << what;
}

// Under parallel view rays the perspective warps have nothing to do: each names it and gives the
// focused map itself.
TEST(OrthographicTown, EveryPerspectiveWarpNamesTheCameraAndGivesTheFocusedMap) {
    const ShadowInputs in = gather_inputs(orthographic_town());
    const ShadowSetup focused = run(method_or_throw("focused"), in);
    ASSERT_EQ(focused.maps.size(), 1u);
    for (const std::string name : {"psm", "lispsm", "tsm", "xpsm"}) {
        const ShadowSetup setup = run(method_or_throw(name), in);
        EXPECT_TRUE(has_note(setup.fallbacks, NoteKind::orthographic_camera))
            << name << ": " << describe(setup.fallbacks);
        expect_same_maps(setup, focused, name);
    }
    const Method& cascades = method_or_throw("cascades");
    const ShadowSetup warped =
        cascades.compute_maps(in, resolve_settings("cascades", cascades.settings, {{"warp", "lispsm"}}), nullptr);
    EXPECT_TRUE(has_note(warped.fallbacks, NoteKind::orthographic_camera)) << describe(warped.fallbacks);
    EXPECT_FALSE(has_note(run(cascades, in).fallbacks, NoteKind::orthographic_camera)) << "splits need no warp";
}

// A spot or a point light under an orthographic camera: the light's own perspective is the map's (the
// focused map judges the view as well as under a sun), and the warps of the camera's perspective
// fall back to it as under a sun.
TEST(OrthographicTown, SpotAndPointLightsAreJudgedAsUnderASun) {
    for (const LightType light : {LightType::spot, LightType::point}) {
        const MeasureContext context = prepare_measurement(orthographic_town(light), kWidth, kHeight);
        const Measurement focused = measured(context, "focused");
        ASSERT_GT(focused.error.receiver_pixels, 0u) << to_string(light);
        EXPECT_LT(focused.error.misclassified, 0.05) << to_string(light);
        const ShadowInputs in = gather_inputs(context.scene);
        const ShadowSetup psm = run(method_or_throw("psm"), in);
        EXPECT_TRUE(has_note(psm.fallbacks, NoteKind::orthographic_camera)) << describe(psm.fallbacks);
        expect_same_maps(psm, run(method_or_throw("focused"), in), std::string("psm, ") + to_string(light));
    }
}

// The geometric techniques: planar shadows project casters onto the ground whatever the camera; the
// stencil count rasterizes from an eye, which an orthographic camera lacks: the limit is named.
TEST(OrthographicTown, PlanarShadowsWorkAndVolumesNameTheMissingEye) {
    const MeasureContext context = prepare_measurement(orthographic_town(), kWidth, kHeight);
    const Method& volumes = method_or_throw("volumes");
    const GeometryResult counted = volumes.compute_geometry(context.scene, context.triangles, context.reference,
                                                            resolve_settings("volumes", volumes.settings, {}), nullptr);
    EXPECT_TRUE(has_note(counted.limits, NoteKind::no_eye_point)) << describe(counted.limits);
    EXPECT_EQ(counted.shadowed.size(), context.reference.visible.size());
    const Method& planar = method_or_throw("planar");
    const GeometryResult projected = planar.compute_geometry(context.scene, context.triangles, context.reference,
                                                             resolve_settings("planar", planar.settings, {}), nullptr);
    ASSERT_EQ(projected.shadowed.size(), context.reference.visible.size());
    EXPECT_GT(std::count(projected.shadowed.begin(), projected.shadowed.end(), 1), 0) << "no shadow on the ground";
}
