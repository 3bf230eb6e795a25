// The lookup's filters and biases (core/lookup/): the closed forms they rest on, the invariants of
// their taps, PCSS's penumbra against the area light's exact one, the biases' world lengths, and
// the settings refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "lookup/chebyshev.hpp"
#include "lookup/kernel_taps.hpp"
#include "lookup/pcss.hpp"
#include "lookup/shadow_reader.hpp"
#include "metrics/measurement.hpp"
#include "raster/depth_map.hpp"
#include "registry/method.hpp"
#include "scene/tessellation.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

// The method's settings with `overrides`, resolved as the CLI resolves them.
Settings focused_with(const std::map<std::string, std::string>& overrides) {
    const Method& m = method_or_throw("focused");
    return resolve_settings(m.name, m.settings, overrides);
}

struct Rasterized {
    ShadowSetup setup;
    DepthMap depth;
};

// The uniform map: it covers the whole scene, wherever the camera looks.
Rasterized uniform_maps(const Scene& scene, int resolution) {
    const Method& m = method_or_throw("uniform");
    Rasterized r;
    r.setup = m.compute_maps(gather_inputs(scene), resolve_settings(m.name, m.settings, {}), nullptr);
    r.depth = rasterize_depth(tessellate(scene), caster_flags(scene), r.setup, resolution);
    return r;
}

}  // namespace

// Chebyshev's one-tailed bound with the square the seed drops: σ² / (σ² + (t − μ)²).
TEST(Chebyshev, TheBoundAndItsBleedingReductionMatchTheClosedForms) {
    const double p = chebyshev_upper_bound(0.3, 0.04, 0.55);
    EXPECT_NEAR(p, 0.04 / (0.04 + 0.0625), 1e-12);
    EXPECT_NEAR(p, 0.390, 5e-4);
    EXPECT_NEAR(reduce_light_bleeding(p, 0.15), 0.283, 5e-4);
    EXPECT_NEAR(reduce_light_bleeding(p, 0.39), 0.0, 5e-4) << "0.39 is the bound to two places: 0 to three";
    EXPECT_EQ(reduce_light_bleeding(p, p), 0.0);
    EXPECT_EQ(reduce_light_bleeding(p, 0.6), 0.0);
    EXPECT_EQ(reduce_light_bleeding(p, 0.0), p);
    EXPECT_EQ(chebyshev_upper_bound(0.3, 0.04, 0.3), 1.0) << "a receiver at the mean depth is lit";
    EXPECT_NEAR(evsm_exponent_limit(), 44.36, 0.005);
    EXPECT_TRUE(std::isfinite(float(std::exp(2.0 * evsm_exponent_limit()) * 0.999)));
}

// Seed 001's PCSS example: w_light = 0.5, d_b = 2, d_r = 5 give w = 0.75; the scene's light gives
// the same through its radius, and a sun 2 Δ tan α.
TEST(Pcss, ThePenumbraWidthMatchesTheClosedForm) {
    EXPECT_DOUBLE_EQ(penumbra_width(5.0, 2.0, 0.5), 0.75);
    const Scene scene = edge_under_a_sphere_light();
    EXPECT_NEAR(penumbra_width(scene.light, {0.0, 0.0, 0.0}, 3.0), 0.75, 1e-12);
    EXPECT_NEAR(blocker_search_radius(scene.light, {0.0, 0.0, 0.0}, 3.0), 0.375, 1e-12);
    const Light sun{.direction = {0, -1, 0}, .angular_radius_deg = 0.5};
    EXPECT_NEAR(penumbra_width(sun, {0, 0, 0}, 10.0), 20.0 * std::tan(glm::radians(0.5)), 1e-12);
    EXPECT_EQ(penumbra_width(Light{}, {0, 0, 0}, 10.0), 0.0) << "a sun without size: hard";
}

TEST(KernelTaps, WeightsSumToOneAndTapsStayInTheirKernel) {
    for (PcfKernel kernel : {PcfKernel::box, PcfKernel::tent, PcfKernel::poisson})
        for (int n : {1, 2, 3, 5, 9}) {
            const std::vector<KernelTap> taps = kernel_taps(kernel, n);
            ASSERT_EQ(int(taps.size()), n * n);
            double total = 0.0;
            for (const KernelTap& t : taps) {
                total += t.weight;
                EXPECT_GT(t.weight, 0.0);
                EXPECT_LE(kernel == PcfKernel::poisson ? glm::length(t.offset)
                                                       : std::max(std::abs(t.offset.x), std::abs(t.offset.y)),
                          1.0 + 1e-12);
            }
            EXPECT_NEAR(total, 1.0, 1e-12) << to_string(kernel) << " " << n;
        }
    const std::vector<KernelTap> tent = kernel_taps(PcfKernel::tent, 3);
    EXPECT_NEAR(tent[4].weight / tent[0].weight, 4.0, 1e-12) << "centre 1 x 1 against corner 1/2 x 1/2";
    // A Poisson disk: no two of its 16 points closer than half the spacing of a 4 x 4 grid over the disc.
    const std::vector<glm::dvec2>& disk = poisson_disk(16);
    for (size_t i = 0; i < disk.size(); ++i)
        for (size_t j = i + 1; j < disk.size(); ++j) EXPECT_GT(glm::distance(disk[i], disk[j]), 0.25) << i << " " << j;
    EXPECT_NE(pixel_rotation(10, 20), pixel_rotation(11, 20));
    EXPECT_EQ(pixel_rotation(10, 20), pixel_rotation(10, 20));
}

// PCSS on a flat blocker parallel to a flat receiver: the blocker search finds the blocker 3 units
// before the ground, the penumbra is (5 − 2) 0.5 / 2 = 0.75 wide, and the filtered profile follows
// the exact one (the share of the light's disc past the edge) within the taps' granularity.
TEST(Pcss, ThePenumbraBehindAStraightEdgeFollowsTheAreaLight) {
    const Scene scene = edge_under_a_sphere_light();
    const Rasterized maps = uniform_maps(scene, 2048);
    ShadowLookup lookup = lookup_from(focused_with({{"filter", "pcss"}, {"kernel_size", "8"}}));
    const ShadowReader reader(maps.setup, maps.depth, scene.light, lookup);
    const double w = 0.75;
    double deviation = 0.0, first_lit = INFINITY, last_dark = -INFINITY;
    int samples = 0;
    for (double x = -0.6; x <= 0.6; x += 0.01) {
        const double v =
            reader.visibility({.position = {x, 0.0, 0.0}, .normal = {0, 1, 0}, .rotation = pixel_rotation(samples, 0)});
        const double exact = disc_share_beyond(-x / (w / 2));
        deviation += std::abs(v - exact);
        ++samples;
        if (v > 0.02) first_lit = std::min(first_lit, x);
        if (v < 0.98) last_dark = std::max(last_dark, x);
    }
    EXPECT_LT(deviation / samples, 0.04);
    // The disc profile passes 2 % and 98 % at ±0.8953 of the half-width (its segment's area); the
    // filter's span matches within three samples.
    EXPECT_NEAR(last_dark - first_lit, 0.8953 * w, 0.03);
}

// Every filter's visibility lies in [0, 1], is 1 where no caster stands between the point and the
// light (within what a moment filter's float32 texels and bias leave) and 0 deep inside a shadow.
TEST(Filters, VisibilityIsAShareAndAgreesFarFromEdges) {
    const Scene scene = edge_under_a_sphere_light();
    const Rasterized maps = uniform_maps(scene, 1024);
    ASSERT_GE(all_filters().size(), 7u) << "hard, pcf, vsm, evsm, msm, esm, pcss at least";
    for (const FilterDescriptor& descriptor : all_filters())
        for (const char* kernel : {"box", "tent", "poisson"}) {
            const std::string& filter = descriptor.name;
            const ShadowLookup lookup = lookup_from(focused_with({{"filter", filter}, {"pcf_kernel", kernel}}));
            const ShadowReader reader(maps.setup, maps.depth, scene.light, lookup);
            for (double x = -3.0; x <= 3.0; x += 0.05) {
                const double v = reader.visibility({.position = {x, 0.0, 0.3}, .normal = {0, 1, 0}, .rotation = x});
                ASSERT_GE(v, 0.0) << filter << " " << x;
                ASSERT_LE(v, 1.0) << filter << " " << x;
            }
            // 1 but for MSM's moment bias (α 13/16 of the share lies at nearer depths) and ESM's
            // e^c rounded to a float32 texel
            EXPECT_NEAR(reader.visibility({.position = {2.0, 0.0, 0.3}, .normal = {0, 1, 0}}), 1.0, 1e-4) << filter;
            EXPECT_LT(reader.visibility({.position = {-2.0, 0.0, 0.3}, .normal = {0, 1, 0}}), 0.02) << filter;
        }
}

// A constant bias is a world length along the light whatever the map's perspective: under a point
// light's perspective map, a point b below the blocker is shadowed by a bias a little under b and
// lit by one a little over (before the fix, a bias applied ahead of the division shrank by w).
TEST(DepthBias, AConstantBiasIsAWorldLengthUnderAPerspectiveMap) {
    const Scene scene = edge_under_a_sphere_light();
    const Rasterized maps = uniform_maps(scene, 2048);
    const glm::dmat4& m = maps.setup.maps[0].world_to_uvz;
    ASSERT_GT(glm::length(glm::dvec3(m[0][3], m[1][3], m[2][3])), 0.0)
        << "a perspective map: w changes along the light";
    const Light light = scene.light;
    for (double below : {0.05, 0.2, 1.0}) {
        const glm::dvec3 p(-0.5, 3.0 - below, 0.2);  // under the blocker at height 3
        const glm::dvec3 towards_p = glm::normalize(p - light.position);
        const double along = below / -towards_p.y;  // the distance to the blocker along the light ray
        EXPECT_TRUE(in_shadow(maps.depth, maps.setup, p, 0.9 * along, light)) << below;
        EXPECT_FALSE(in_shadow(maps.depth, maps.setup, p, 1.1 * along, light)) << below;
    }
}

// A ground lit at a grazing angle: without bias it shadows itself (acne); the slope-scaled bias,
// the normal offset and the receiver plane each remove most of it.
TEST(DepthBias, EachBiasRemovesTheAcneOfAGrazingLight) {
    Scene scene = edge_under_a_sphere_light();
    scene.objects.resize(1);  // the ground alone, casting onto itself: every false shadow is acne
    scene.objects[0].casts = true;
    scene.light = {.direction = glm::normalize(glm::dvec3(1.0, -0.08, 0.3))};
    scene.camera.position = {0, 6, 6};
    scene.camera.target = {0, 0, 0};
    scene.camera.up = {0, 1, 0};
    scene.camera.fov_y_deg = 50;
    scene.camera.aspect = 1;
    const MeasureContext context = prepare_measurement(scene, 160, 160);
    const Method& focused = method_or_throw("focused");
    auto acne = [&](const std::map<std::string, std::string>& bias) {
        return measure(context, focused, focused_with(bias), 256, -1.0).error.false_shadow;
    };
    const double none = acne({{"bias_slope", "0"}});
    EXPECT_GT(none, 0.2) << "half the texels of a tilted plane lie above it";
    EXPECT_LT(acne({}), 0.01 * none);
    EXPECT_LT(acne({{"bias_slope", "0"}, {"bias_normal", "1.5"}}), 0.05 * none);
    EXPECT_LT(acne({{"bias_slope", "0"}, {"bias_receiver_plane", "on"}, {"bias_constant", "1e-4"}}), 0.05 * none);
}

// VSM's light bleeding: a receiver under a low caster whose filter region also holds a high one
// (nearer the light) reads a wide variance with a mean between the two, and Chebyshev's bound lights
// it although the low caster shadows it fully; the reduction cuts that tail.
TEST(Vsm, LightBleedingFallsWithTheReduction) {
    const MeasureContext context = prepare_measurement(ground_under_a_low_and_a_high_caster(), 160, 160, 16);
    const Method& uniform = method_or_throw("uniform");
    auto bleeding = [&](const char* reduction) {
        const Settings settings = resolve_settings(
            "uniform", uniform.settings, {{"filter", "vsm"}, {"kernel_size", "9"}, {"bleed_reduction", reduction}});
        return measure(context, uniform, settings, 512, -1.0).error.visibility.light_bleeding;
    };
    const double plain = bleeding("0"), reduced = bleeding("0.3"), strong = bleeding("0.7");
    EXPECT_GT(plain, 0.01);
    EXPECT_LT(reduced, plain);
    EXPECT_LE(strong, reduced);
}

// The moments are blurred within each map's tile: a tile of one depth stays that depth, and a
// neighbouring tile's texels never leak into it.
TEST(MomentMap, TheBlurStaysInsideEachTile) {
    ShadowSetup setup;
    setup.maps.resize(2);
    setup.maps[0].viewport = {0.0, 0.0, 0.5, 1.0};
    setup.maps[1].viewport = {0.5, 0.0, 1.0, 1.0};
    DepthMap depth(16, {});
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) depth.set(x, y, x < 8 ? 0.25 : 0.75);
    const MomentMap moments = blurred_moments(depth, setup, {.kind = "vsm", .kernel_size = 5});
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            const float d = x < 8 ? 0.25f : 0.75f;
            ASSERT_FLOAT_EQ(moments.at(x, y).x, d) << x << ", " << y;
            ASSERT_FLOAT_EQ(moments.at(x, y).y, d * d) << x << ", " << y;
        }
    EXPECT_NEAR(sample_moments(moments, setup.maps[0], {0.99, 0.5}).x, 0.25, 1e-7) << "bilinear kept in its tile";
}

// The blur is a box of side N (an even side reaching one texel further toward −u, −v), edges
// clamped to the tile: against the direct sum of the window on random depths.
TEST(MomentMap, TheBlurIsTheClampedBoxAverage) {
    ShadowSetup setup;
    setup.maps.resize(1);
    setup.maps[0].viewport = {0.25, 0.0, 0.75, 0.5};  // texels 4..11 x 0..7 of 16
    std::mt19937 random(5);
    std::uniform_real_distribution<float> depth01(0.0f, 1.0f);
    DepthMap depth(16, {});
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) depth.set(x, y, depth01(random));
    for (int side : {1, 2, 3, 4}) {
        const MomentMap moments = blurred_moments(depth, setup, {.kind = "vsm", .kernel_size = side});
        const int before = side / 2, after = side - 1 - before;
        for (int y = 0; y < 8; ++y)
            for (int x = 4; x < 12; ++x) {
                double sum = 0.0;
                for (int j = -before; j <= after; ++j)
                    for (int i = -before; i <= after; ++i)
                        sum += depth.at(std::clamp(x + i, 4, 11), std::clamp(y + j, 0, 7));
                ASSERT_NEAR(moments.at(x, y).x, sum / (side * side), 1e-6) << side << ": " << x << ", " << y;
            }
        EXPECT_EQ(moments.at(0, 0).x, depth.at(0, 0)) << "outside every tile: unblurred";
    }
}

// Every map method lists each lookup setting once, after its own, and the geometric techniques none;
// PSM's slope-scaled bias is the other maps' (its old 0.25 left acne on a lone box: psm.hpp).
TEST(LookupSettings, EveryMapMethodListsEachOnce) {
    for (int call = 0; call < 2; ++call)  // the registry is built once, whatever the calls
        for (const Method& m : all_methods()) {
            std::map<std::string, int> seen;
            for (const SettingSpec& spec : m.settings) ++seen[spec.name];
            for (const SettingSpec& spec : lookup_settings())
                EXPECT_EQ(seen[spec.name], m.makes_maps() ? 1 : 0) << m.name << " " << spec.name;
        }
    const Method& psm = method_or_throw("psm");
    EXPECT_EQ(resolve_settings("psm", psm.settings, {}).number("bias_slope"), 1.0);
    EXPECT_EQ(focused_with({}).number("bias_slope"), 1.0);
    EXPECT_TRUE(filters_reading("bias_slope").empty());
    EXPECT_EQ(filters_reading("evsm_positive"), std::vector<std::string>{"evsm"});
}

TEST(LookupSettings, BadSettingsAreRefusedByName) {
    const auto refused = [](const std::map<std::string, std::string>& overrides, const std::string& name) {
        try {
            lookup_from(focused_with(overrides));
        } catch (const std::invalid_argument& e) {
            return std::string(e.what()).find(name) != std::string::npos;
        }
        return false;
    };
    EXPECT_TRUE(refused({{"kernel_size", "0"}}, "kernel_size"));
    EXPECT_TRUE(refused({{"kernel_size", "10"}}, "kernel_size"));
    EXPECT_TRUE(refused({{"kernel_size", "2.5"}}, "kernel_size"));
    EXPECT_TRUE(refused({{"evsm_positive", "45"}}, "evsm_positive"));
    EXPECT_TRUE(refused({{"evsm_negative", "44.5"}}, "evsm_negative"));
    EXPECT_TRUE(refused({{"filter_radius", "0"}}, "filter_radius"));
    EXPECT_TRUE(refused({{"bias_constant", "-1"}}, "bias_constant"));
    EXPECT_TRUE(refused({{"filter", "vsm"}, {"filter_world_radius", "0.5"}}, "filter_world_radius"));
    EXPECT_TRUE(refused({{"filter", "blur"}}, "filter"));
    EXPECT_TRUE(refused({{"depth_format", "unorm32"}}, "depth_format"));
    EXPECT_TRUE(refused({{"depth_reversed", "yes"}}, "depth_reversed"));
    EXPECT_NO_THROW(lookup_from(focused_with({{"evsm_positive", "44.36"}})));
}

// The depth format is a lookup setting: float32, not reversed, unless the settings say otherwise,
// and every filter reads it (it sits with the biases).
TEST(LookupSettings, TheDepthFormatSettingsReachTheLookup) {
    EXPECT_EQ(lookup_from(focused_with({})).format, DepthFormat{});
    EXPECT_EQ(lookup_from(focused_with({{"depth_format", "unorm16"}})).format,
              (DepthFormat{.encoding = DepthEncoding::unorm16}));
    EXPECT_EQ(lookup_from(focused_with({{"depth_format", "unorm24"}, {"depth_reversed", "on"}})).format,
              (DepthFormat{.encoding = DepthEncoding::unorm24, .reversed = true}));
    EXPECT_EQ(lookup_from(focused_with({{"depth_reversed", "on"}}), 0.01).format, (DepthFormat{.reversed = true}))
        << "a constant --bias replaces the biases, not the format";
    EXPECT_TRUE(filters_reading("depth_format").empty());
    EXPECT_TRUE(is_lookup_setting("depth_reversed"));
}
