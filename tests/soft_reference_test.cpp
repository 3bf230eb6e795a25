// The soft reference of an area light: stratified samples that cover the disc evenly, and the
// penumbra behind a straight edge in closed form (a flat blocker parallel to a flat receiver: its
// width (d_r - d_b) w_light / d_b, its profile the share of the light's disc on one side of a line).
#include <gtest/gtest.h>

#include <cmath>

#include "reference/exact_shadows.hpp"
#include "reference/light_samples.hpp"
#include "scene/scene_loader.hpp"
#include "scene/tessellation.hpp"
#include "test_support.hpp"

using namespace shadowlab;

using namespace shadowlab::testing;

TEST(LightSamples, StratifiedSamplesCoverTheDiscEvenly) {
    const std::vector<glm::dvec2> disc = stratified_disc(1000, 7);
    ASSERT_EQ(disc.size(), 1024u);  // rounded up to 32 x 32
    int inner = 0;
    glm::dvec2 mean(0.0);
    for (const glm::dvec2& s : disc) {
        EXPECT_LE(glm::length(s), 1.0 + 1e-12);
        inner += glm::length(s) < 0.5;
        mean += s / double(disc.size());
    }
    EXPECT_NEAR(inner / 1024.0, 0.25, 0.01) << "a quarter of the area within half the radius";
    EXPECT_LT(glm::length(mean), 0.01);
    EXPECT_EQ(stratified_disc(64, 3), stratified_disc(64, 3)) << "deterministic";
    EXPECT_NE(stratified_disc(64, 3), stratified_disc(64, 4));
}

TEST(LightSamples, TheSunsDirectionsLieWithinItsAngularRadius) {
    const Light sun{.direction = glm::normalize(glm::dvec3(0.3, -1.0, 0.2)), .angular_radius_deg = 0.5};
    double widest = 0.0;
    for (const glm::dvec2& s : stratified_disc(256, 1))
        widest =
            std::max(widest, glm::degrees(std::acos(std::min(1.0, glm::dot(sun_direction(sun, s), -sun.direction)))));
    EXPECT_LE(widest, 0.5 + 1e-9);
    EXPECT_GT(widest, 0.45);
}

// Seed 001's PCSS estimate, w = (d_r - d_b) w_light / d_b = (5 - 2) 0.5 / 2 = 0.75: the measured
// penumbra spans it and follows the disc's profile within the samples' noise.
TEST(SoftReference, ThePenumbraBehindAStraightEdgeMatchesTheClosedForm) {
    const Scene scene = edge_under_a_sphere_light();
    constexpr int kWidth = 400, kHeight = 8, kSamples = 256;
    const ReferenceImage soft = soft_reference(scene, tessellate(scene), kWidth, kHeight, kSamples);
    ASSERT_EQ(soft.light_samples, kSamples);
    const double d_b = 2.0, d_r = 5.0, w_light = 0.5;
    const double penumbra = (d_r - d_b) * w_light / d_b;
    EXPECT_DOUBLE_EQ(penumbra, 0.75);
    double deviation = 0.0, widest_error = 0.0, first_lit = INFINITY, last_dark = -INFINITY;
    int judged = 0;
    for (int x = 0; x < kWidth; ++x) {
        const size_t i = size_t(kHeight / 2) * kWidth + x;
        ASSERT_TRUE(soft.visible[i]);
        const double ground_x = soft.position[i].x;
        // From ground x the light is seen past the edge where its disc coordinate ξ > -x d_b / (d_r - d_b):
        // in units of its radius, beyond u = -x / (w / 2).
        const double expected = disc_share_beyond(-ground_x / (penumbra / 2));
        deviation += std::abs(soft.visibility[i] - expected);
        widest_error = std::max(widest_error, std::abs(soft.visibility[i] - expected));
        ++judged;
        if (soft.visibility[i] > 0.0) first_lit = std::min(first_lit, ground_x);
        if (soft.visibility[i] < 1.0) last_dark = std::max(last_dark, ground_x);
    }
    EXPECT_LT(deviation / judged, 0.01);
    EXPECT_LT(widest_error, 0.05);
    EXPECT_NEAR(last_dark - first_lit, penumbra, 0.03 * penumbra) << "the penumbra's measured width";
    EXPECT_LT(visibility_standard_error(0.5, kSamples), 0.032);
}

// Without a radius the soft reference is the hard one: every share is 0 or 1, as `lit` says.
TEST(SoftReference, APointLightCastsHardShadows) {
    Scene scene = edge_under_a_sphere_light();
    scene.light.radius = 0.0;
    const ReferenceImage soft = soft_reference(scene, tessellate(scene), 100, 4, 16);
    for (size_t i = 0; i < soft.visible.size(); ++i)
        if (soft.visible[i]) {
            EXPECT_EQ(soft.visibility[i], soft.lit[i] ? 1.0f : 0.0f) << i;
        }
}
