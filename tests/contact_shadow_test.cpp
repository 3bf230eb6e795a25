// Contact shadows (lookup/contact_shadow.hpp): the march through the camera's depth image in closed
// form, off changing nothing, and what it adds to a map on a planted scene: the false light of a
// large normal offset where the box meets the ground, and the false shadow of a surface taken too
// thick, named by its cause.
#include <gtest/gtest.h>

#include <iostream>

#include "lookup/contact_shadow.hpp"
#include "metrics/diagnosis.hpp"
#include "reference/camera_rays.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using shadowlab::testing::source_path;

namespace {

// A camera 10 units before the plane z = 0, looking straight at it: every pixel of the plane is at
// view depth 10.
Camera facing_the_plane() {
    Camera camera;
    camera.position = {0.0, 0.0, 10.0};
    camera.target = {0.0, 0.0, 0.0};
    camera.aspect = 1.0;
    return camera;
}

// The plane's depth image, the pixels whose rays meet it at x in [0.3, 0.5] raised `wall_in_front`
// toward the camera: a wall standing on the plane, seen face on.
CameraDepthImage plane_with_a_wall(double wall_in_front) {
    const Camera camera = facing_the_plane();
    constexpr int side = 200;  // a pixel spans 0.058 units of the plane
    CameraDepthImage image(camera, side, side);
    const CameraRays rays(camera, side, side);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            const EyeRay ray = rays.ray(x, y);  // its t is the view depth
            const double to_plane = -ray.origin.z / ray.direction.z;
            const glm::dvec3 on_plane = ray.origin + ray.direction * to_plane;
            const bool wall = on_plane.x >= 0.3 && on_plane.x <= 0.5;
            const glm::dvec3 seen = ray.origin + ray.direction * (to_plane - (wall ? wall_in_front : 0.0));
            image.window_depth[size_t(y) * side + x] = float(image.window_depth_of(seen));
        }
    return image;
}

// The receiver 0.01 before the plane (well above the float window depths' rounding, 6e-5 at view
// depth 10), the light along +x: the samples stay 0.01 before the plane.
constexpr glm::dvec3 kReceiver{0.0, 0.0, 0.01}, kTowardWall{1.0, 0.0, 0.0};

struct MeasuredPair {
    Measurement without, with;
};

// The same run without and with contact shadows.
MeasuredPair measured_with_and_without(const Scene& scene, std::map<std::string, std::string> settings,
                                       const std::map<std::string, std::string>& contact) {
    const MeasureContext context = prepare_measurement(scene, 480, 270);
    const Method& focused = method_or_throw("focused");
    MeasuredPair pair;
    pair.without = measure(context, focused, resolve_settings("focused", focused.settings, settings), 1024, -1.0);
    settings.insert(contact.begin(), contact.end());
    pair.with = measure(context, focused, resolve_settings("focused", focused.settings, settings), 1024, -1.0);
    return pair;
}

size_t pixels_judged(const ShadowError& e, PixelVerdict verdict) {
    return size_t(std::count(e.verdicts.begin(), e.verdicts.end(), verdict));
}

}  // namespace

// Closed form: from the receiver toward +x, samples every 0.1 up to 1, all at view depth 9.99. The
// wall's pixels (x in [0.3, 0.5]) at 9.95 hold samples 0.04 behind them: within a thickness of 0.1,
// occluded; at 9.5, 0.49 behind: the samples pass behind the wall, not inside it.
TEST(ContactShadow, ASampleBehindTheImagesSurfaceWithinTheThicknessOccludes) {
    const ContactShadow contact{.length = 1.0, .steps = 10, .thickness = 0.1};
    EXPECT_EQ(contact_visibility(contact, plane_with_a_wall(0.05), kReceiver, kTowardWall), 0.0);
    EXPECT_EQ(contact_visibility(contact, plane_with_a_wall(0.0), kReceiver, kTowardWall), 1.0) << "in the open";
    EXPECT_EQ(contact_visibility(contact, plane_with_a_wall(0.5), kReceiver, kTowardWall), 1.0)
        << "a surface more than the thickness in front: the ray passes behind it";
    EXPECT_EQ(contact_visibility(contact, plane_with_a_wall(-0.05), kReceiver, kTowardWall), 1.0)
        << "a surface behind the samples";
    EXPECT_EQ(contact_visibility({.length = 0.25, .steps = 10, .thickness = 0.1}, plane_with_a_wall(0.05), kReceiver,
                                 kTowardWall),
              1.0)
        << "the march ends before the wall";
    EXPECT_EQ(contact_visibility(contact, plane_with_a_wall(0.05), kReceiver, -kTowardWall), 1.0)
        << "marching away from the wall";
    EXPECT_EQ(contact_visibility({.length = 1.0, .steps = 10, .thickness = 0.6}, plane_with_a_wall(0.5), kReceiver,
                                 kTowardWall),
              0.0)
        << "a thicker surface holds the samples 0.5 behind it";
}

// A sample off the image ends the march: nothing is known there.
TEST(ContactShadow, TheMarchEndsWhereItLeavesTheImage) {
    const ContactShadow contact{.length = 100.0, .steps = 4, .thickness = 1e9};  // the first sample at x = 25
    EXPECT_EQ(contact_visibility(contact, plane_with_a_wall(0.05), kReceiver, kTowardWall), 1.0);
    EXPECT_EQ(contact_visibility(contact, plane_with_a_wall(0.05), kReceiver, glm::dvec3(0.0, 0.0, 1.0)), 1.0)
        << "toward the eye and past it";
}

// Off (contact_length 0) nothing is marched: whatever the steps and the thickness, every
// visibility is the map's, bit for bit, and so is every verdict.
TEST(ContactShadow, OffChangesNothing) {
    const MeasuredPair pair =
        measured_with_and_without(load_scene(source_path("data/scenes/planks_on_plane.json")), {{"bias_normal", "8"}},
                                  {{"contact_steps", "64"}, {"contact_thickness", "1000"}});
    ASSERT_GT(pair.without.error.receiver_pixels, 10000u);
    EXPECT_EQ(pair.with.error.verdicts, pair.without.error.verdicts);
    EXPECT_EQ(pair.with.error.visibility.rmse, pair.without.error.visibility.rmse);
    EXPECT_EQ(pair.with.error.causes, pair.without.error.causes);
}

// Planted: a box and low planks on a plane under a sun 30° high (planks_on_plane), read with a
// normal offset of 8 texels, which lifts the planks' shadows off them and the box's off its foot
// (peter panning: false light along the contacts). Contact shadows over half a unit restore at
// least half of that false light, and add little false shadow.
TEST(ContactShadow, RemovesAtLeastHalfTheFalseLightOfALargeNormalOffset) {
    const MeasuredPair pair =
        measured_with_and_without(load_scene(source_path("data/scenes/planks_on_plane.json")), {{"bias_normal", "8"}},
                                  {{"contact_length", "0.5"}, {"contact_steps", "8"}, {"contact_thickness", "0.1"}});
    const size_t light_before = pixels_judged(pair.without.error, PixelVerdict::false_light),
                 light_after = pixels_judged(pair.with.error, PixelVerdict::false_light),
                 shadow_before = pixels_judged(pair.without.error, PixelVerdict::false_shadow),
                 shadow_after = pixels_judged(pair.with.error, PixelVerdict::false_shadow);
    std::cout << "false light " << light_before << " -> " << light_after << ", false shadow " << shadow_before << " -> "
              << shadow_after << " of " << pair.with.error.receiver_pixels << " receiver pixels\n";
    ASSERT_GT(light_before, 2000u) << "the normal offset lifts the shadows off their casters";
    EXPECT_LE(2 * light_after, light_before);
    EXPECT_LT(shadow_after, shadow_before + light_before / 4) << "contact shadows add little false shadow here";
}

// A surface taken 2 units deep: samples passing behind the box's and the planks' silhouettes are
// held inside them, false shadow the map alone does not cast. Those pixels are named `contact`,
// the first cause, and its remedy, a surface half as thick, sets a share of them right.
TEST(ContactShadow, FalseShadowOfSurfacesTakenTooThickIsNamedContact) {
    const Scene scene = load_scene(source_path("data/scenes/planks_on_plane.json"));
    const MeasureContext context = prepare_measurement(scene, 480, 270);
    const Method& focused = method_or_throw("focused");
    const Settings settings =
        resolve_settings("focused", focused.settings, {{"contact_length", "0.5"}, {"contact_thickness", "2"}});
    const Measurement m = measure(context, focused, settings, 1024, -1.0);
    const Diagnosis d = diagnose(context, focused, settings, 1024, -1.0, m);
    ASSERT_FALSE(d.causes.empty());
    const CauseCount& top = d.causes.front();
    EXPECT_EQ(top.kind, PixelCause::contact);
    EXPECT_GT(top.pixels, 100u);
    ASSERT_TRUE(top.remedy);
    EXPECT_EQ(top.remedy->change, "contact_thickness 2 → 1");
    EXPECT_GT(top.remedy->removes, 0.2);
}
