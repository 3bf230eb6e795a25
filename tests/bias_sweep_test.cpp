// The acne / peter-panning curve: a box on a plane under a light 38° above it, so that the lit plane
// faces the light at an angle and shadows itself without bias; the slope-scaled bias swept upward
// trades that acne for a shadow lifted off the box.
#include <gtest/gtest.h>

#include <algorithm>

#include "metrics/bias_sweep.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using shadowlab::testing::source_path;

namespace {

constexpr int kResolution = 512;

MeasureContext tilted_light_on_box(int width = 160, int height = 90) {
    Scene scene = load_scene(source_path("data/scenes/box_on_plane.json"));
    scene.light.direction = glm::normalize(glm::dvec3(0.6, -0.57, -0.4));  // 38° above the plane
    return prepare_measurement(scene, width, height);
}

BiasCurve slope_curve(const MeasureContext& context, const std::string& method) {
    return sweep_bias(context, method_or_throw(method), {}, kResolution, "bias_slope",
                      default_bias_values(context, "bias_slope", kResolution));
}

}  // namespace

TEST(BiasSweep, NoSlopeBiasLeavesAcneOnTheLitPlane) {
    const MeasureContext context = tilted_light_on_box();
    const BiasCurve curve = sweep_bias(context, method_or_throw("focused"), {}, kResolution, "bias_slope", {0.0});
    EXPECT_GT(curve.points.front().false_shadow, 0.01) << "the plane's depth crosses each texel's stored depth";
}

// A hard lookup shadows a pixel while its biased depth lies behind the stored depth, and the
// slope-scaled bias at every pixel grows in proportion to the scale: as the scale grows a verdict
// can only turn from shadowed to lit, never back. So false shadow never rises and false light never
// falls, exactly (a tolerance of no pixel): the maps, the pixels and their stored depths are the same
// at every value.
TEST(BiasSweep, AcneFallsAndPeterPanningRisesWithTheSlopeScale) {
    const MeasureContext context = tilted_light_on_box();
    for (const std::string method : {"focused", "lispsm", "cascades"}) {
        const BiasCurve curve = slope_curve(context, method);
        ASSERT_GE(curve.points.size(), 12u);
        for (size_t i = 1; i < curve.points.size(); ++i) {
            const BiasPoint &before = curve.points[i - 1], &after = curve.points[i];
            ASSERT_GT(after.value, before.value);
            EXPECT_LE(after.false_shadow, before.false_shadow) << method << " at " << after.value;
            EXPECT_GE(after.false_light, before.false_light) << method << " at " << after.value;
        }
        EXPECT_LT(curve.points.back().false_shadow, curve.points.front().false_shadow) << method;
        EXPECT_GT(curve.points.back().false_light, curve.points.front().false_light)
            << method << ": 32 slope-scaled biases lift the box's shadow off its base";
    }
}

TEST(BiasSweep, TheBestPointIsTheLeastMisclassified) {
    const MeasureContext context = tilted_light_on_box();
    const BiasCurve curve = slope_curve(context, "focused");
    const BiasPoint& best = curve.points.at(curve.best);
    for (const BiasPoint& p : curve.points) {
        EXPECT_LE(best.misclassified, p.misclassified) << p.value;
        if (p.misclassified == best.misclassified) {
            EXPECT_LE(best.value, p.value) << "ties go to the smaller bias";
        }
    }
    EXPECT_LT(best.misclassified, curve.points.front().misclassified) << "some bias beats none";
}

TEST(BiasSweep, NormalAndConstantSweepsHoldTheSlopeBiasAtZero) {
    EXPECT_EQ(bias_sweep_settings({}, "bias_normal").at("bias_slope"), "0");
    EXPECT_EQ(bias_sweep_settings({}, "bias_constant").at("bias_slope"), "0");
    EXPECT_EQ(bias_sweep_settings({{"bias_slope", "2"}}, "bias_normal").at("bias_slope"), "2") << "unless asked";
    EXPECT_FALSE(bias_sweep_settings({}, "bias_slope").count("bias_slope"));
    EXPECT_THROW(bias_sweep_settings({{"bias_slope", "2"}}, "bias_slope"), std::invalid_argument);
    EXPECT_THROW(bias_sweep_settings({}, "filter"), std::invalid_argument);
}

// The constant ladder counts texel widths: halving the texels doubles every value.
TEST(BiasSweep, TheConstantLadderScalesWithATexelsWidth) {
    const MeasureContext context = tilted_light_on_box(32, 18);
    const std::vector<double> fine = default_bias_values(context, "bias_constant", 1024),
                              coarse = default_bias_values(context, "bias_constant", 512);
    ASSERT_EQ(fine.size(), coarse.size());
    EXPECT_EQ(fine.front(), 0.0);
    for (size_t i = 1; i < fine.size(); ++i) EXPECT_NEAR(coarse[i], 2.0 * fine[i], 1e-12 * coarse[i]);
    EXPECT_NEAR(fine.back() / fine[1], 4096.0, 1e-9) << "1/64 to 64 texel widths";
}

TEST(BiasSweep, AGeometricTechniqueHasNoBiasToSweep) {
    const MeasureContext context = tilted_light_on_box(32, 18);
    for (const Method& method : all_methods())
        if (!method.makes_maps()) {
            EXPECT_THROW(sweep_bias(context, method, {}, kResolution, "bias_slope", {1.0}), std::invalid_argument);
        }
}
