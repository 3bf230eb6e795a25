// Moment shadow maps (Peters and Klein 2015) and exponential shadow maps (Annen et al. 2008): the
// closed forms they rest on, the 16-bit basis, and the light bleeding MSM removes where VSM lights.
#include <gtest/gtest.h>

#include <cmath>

#include "lookup/chebyshev.hpp"
#include "lookup/exponential_shadow.hpp"
#include "lookup/lookup_settings.hpp"
#include "lookup/moment_shadow.hpp"
#include "lookup/shadow_reader.hpp"
#include "maps/map_lookup.hpp"
#include "metrics/measurement.hpp"
#include "raster/depth_map.hpp"
#include "registry/method.hpp"
#include "scene/scene_loader.hpp"
#include "scene/tessellation.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

// The moments of depths `near` and `far` in the shares w and 1 − w.
glm::dvec4 two_depths(double near, double far, double w) {
    return w * power_moments(near) + (1.0 - w) * power_moments(far);
}

Settings uniform_with(const std::map<std::string, std::string>& overrides) {
    const Method& m = method_or_throw("uniform");
    return resolve_settings(m.name, m.settings, overrides);
}

}  // namespace

// Four moments of two depths determine them (the distribution is on the boundary of the moment
// space), so the sharpest lower bound on the share nearer the light is that share itself: 0 in
// front of both, w between them, 1 behind both (Peters and Klein, Section 3: the bound is sharp).
// Chebyshev's bound on the same depths lights the receiver behind both: VSM's light bleeding.
TEST(Msm, TheHamburgerBoundOfTwoDepthsIsTheShareNearerTheLight) {
    const double alpha = 1e-7;  // enough to keep the Hankel matrix of two depths invertible
    for (double w : {0.2, 0.5, 0.8}) {
        const glm::dvec4 b = two_depths(0.3, 0.6, w);
        EXPECT_NEAR(hamburger_shadow_intensity(b, 0.2, alpha), 0.0, 1e-6) << w;
        EXPECT_NEAR(hamburger_shadow_intensity(b, 0.45, alpha), w, 1e-3) << w;
        EXPECT_NEAR(hamburger_shadow_intensity(b, 0.7, alpha), 1.0, 1e-3) << w;
        const double mean = b.x, variance = b.y - b.x * b.x;
        EXPECT_GT(chebyshev_upper_bound(mean, variance, 0.7), 0.1) << "VSM lights what both depths shadow";
    }
}

// One depth: the moment bias spreads it a little, and the bound still rises from 0 to 1 across it,
// within a sliver: the receiver just behind a lone caster is in shadow, even a caster at depth 0
// (where a fitted map puts its nearest) with the receiver at 1.
TEST(Msm, OneDepthShadowsWhatLiesBehindIt) {
    const glm::dvec4 b = power_moments(0.4);
    EXPECT_LT(hamburger_shadow_intensity(b, 0.39, 3e-5), 0.01);
    EXPECT_GT(hamburger_shadow_intensity(b, 0.42, 3e-5), 0.98);
    EXPECT_GT(hamburger_shadow_intensity(power_moments(0.0), 1.0, 3e-5), 0.99);
    EXPECT_GT(hamburger_shadow_intensity(power_moments(0.0), 0.05, 3e-5), 0.98);
    double previous = 0.0;  // and never falls with the depth
    for (double z = 0.0; z <= 1.0; z += 0.01) {
        const double g = hamburger_shadow_intensity(two_depths(0.25, 0.7, 0.4), z, 3e-5);
        EXPECT_GE(g, previous - 1e-9) << z;
        previous = g;
    }
}

// The optimized basis: its two published matrices are each other's inverse (to their ten digits),
// every depth's moments land inside [0, 1]⁴ (so that unorm16 holds them), and the bound read from
// moments rounded to 16 bits stays within a few hundredths of the float one with the paper's α.
TEST(Msm, TheOptimizedSixteenBitBasisHoldsEveryDepth) {
    for (double z = 0.0; z <= 1.0; z += 1.0 / 64) {
        const glm::dvec4 power = power_moments(z), optimized = optimized_moments(power);
        for (int k = 0; k < 4; ++k) {
            EXPECT_GE(optimized[k], 0.0) << z << " " << k;
            EXPECT_LE(optimized[k], 1.0) << z << " " << k;
            EXPECT_NEAR(power_from_optimized(optimized)[k], power[k], 1e-8) << z << " " << k;
        }
    }
    const glm::dvec4 b = two_depths(0.3, 0.6, 0.5);
    const glm::dvec4 rounded = power_from_optimized(rounded_to_unorm16(optimized_moments(b)));
    EXPECT_NE(rounded, b) << "rounding changes the moments";
    for (double z : {0.2, 0.45, 0.9})
        EXPECT_NEAR(hamburger_shadow_intensity(rounded, z, 3e-5), hamburger_shadow_intensity(b, z, 3e-5), 0.03) << z;
}

// ESM's value: under a flat blocker, the blurred e^{c z} of one depth z times e^{−c d} is
// e^{−c (d − z)}, d and z the map's depths of the receiver and of the blocker above it.
TEST(Esm, TheVisibilityBehindOneDepthIsTheExponentialOfTheGap) {
    const Scene scene = edge_under_a_sphere_light();
    const Method& uniform = method_or_throw("uniform");
    const ShadowSetup setup = uniform.compute_maps(gather_inputs(scene), uniform_with({}), nullptr);
    const DepthMap depth = rasterize_depth(tessellate(scene), caster_flags(scene), setup, 1024);
    for (double c : {5.0, 20.0}) {
        ShadowLookup lookup = lookup_from(uniform_with({{"filter", "esm"}, {"esm_exponent", std::to_string(c)}}));
        lookup.bias = {.slope_scale = 0.0};
        const ShadowReader reader(setup, depth, scene.light, lookup);
        for (double x : {-3.0, -1.5}) {
            const glm::dvec3 ground(x, 0.0, 0.3);
            const glm::dvec3 blocker = glm::mix(scene.light.position, ground, 0.4);  // at height 3, toward the light
            const double d = world_to_uvz(setup.maps[0], ground).z, z = world_to_uvz(setup.maps[0], blocker).z;
            EXPECT_NEAR(reader.visibility({.position = ground, .normal = {0, 1, 0}}), std::exp(-c * (d - z)), 1e-4)
                << c << " " << x;
        }
        EXPECT_NEAR(reader.visibility({.position = {2.0, 0.0, 0.3}, .normal = {0, 1, 0}}), 1.0, 1e-6)
            << "lit: e^{c z} e^{−c d} >= 1 but for the float32 rounding of e^{c z}";
    }
    EXPECT_NEAR(esm_visibility(std::exp(0.5 * 10.0), 0.6, 10.0), std::exp(-1.0), 1e-12);
    EXPECT_NEAR(esm_exponent_limit(), 88.72, 0.005);
    EXPECT_TRUE(std::isfinite(float(std::exp(esm_exponent_limit()) * 0.999)));
    EXPECT_FALSE(std::isfinite(float(std::exp(esm_exponent_limit() * 1.001))));
}

// Behind two casters, where VSM lights the ground (Vsm.LightBleedingFallsWithTheReduction), MSM's
// bound keeps it dark: its light bleeding is a small share of VSM's, at either storage.
TEST(Msm, BleedsFarLessThanVsmBehindTwoCasters) {
    const MeasureContext context = prepare_measurement(ground_under_a_low_and_a_high_caster(), 160, 160, 16);
    const Method& uniform = method_or_throw("uniform");
    auto bleeding = [&](const char* filter, const char* quantization) {
        const Settings settings =
            uniform_with({{"filter", filter}, {"kernel_size", "9"}, {"msm_quantization", quantization}});
        return measure(context, uniform, settings, 512, -1.0).error.visibility.light_bleeding;
    };
    const double vsm = bleeding("vsm", "float32");
    ASSERT_GT(vsm, 0.01);
    EXPECT_LT(bleeding("msm", "float32"), 0.1 * vsm);
    EXPECT_LT(bleeding("msm", "unorm16"), 0.1 * vsm);
}

// The measure on the shipped town under a sun 0.5° wide: MSM lights fewer of the fully
// shadowed pixels than VSM (0.13 % against 0.37 % at 640×360 and 2048²; here a quarter of the pixels).
TEST(Msm, BleedsLessThanVsmOnTheSunDisc) {
    const MeasureContext context = prepare_measurement(load_scene(source_path("data/scenes/sun_disc.json")), 320, 180);
    const Method& focused = method_or_throw("focused");
    auto bleeding = [&](const char* filter) {
        const Settings settings = resolve_settings(focused.name, focused.settings, {{"filter", filter}});
        return measure(context, focused, settings, 2048, -1.0).error.visibility.light_bleeding;
    };
    const double vsm = bleeding("vsm");
    ASSERT_GT(vsm, 0.0) << "VSM bleeds on the town";
    EXPECT_LT(bleeding("msm"), vsm);
}

// The exponents' limits are the settings' ranges: a float32 texel overflows beyond them.
TEST(Esm, TheExponentBeyondItsLimitIsRefusedByName) {
    EXPECT_THROW(uniform_with({{"esm_exponent", "89"}}), std::invalid_argument);
    EXPECT_NO_THROW(uniform_with({{"esm_exponent", "88.7"}}));
    EXPECT_THROW(uniform_with({{"msm_quantization", "unorm8"}}), std::invalid_argument);
    EXPECT_EQ(lookup_from(uniform_with({{"msm_quantization", "unorm16"}})).filter.msm_quantized, true);
}
