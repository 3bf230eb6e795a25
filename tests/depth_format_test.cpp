// The depth formats (raster/depth_format.hpp) against their closed forms, the rasterizer storing each
// as it says, and what the precision does to a lookup: a 16-bit map over a deep range turns to acne
// where float32 does not.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "maps/clip_conventions.hpp"
#include "metrics/shadow_error.hpp"
#include "raster/depth_map.hpp"
#include "reference/exact_shadows.hpp"
#include "scene/tessellation.hpp"
#include "test_support.hpp"

using namespace shadowlab;

namespace {

// Depths over [0, 1]: the ends, values next to them, and random ones between.
std::vector<double> depths_to_try() {
    std::vector<double> depths{0.0, 1e-9, 1e-6, 0.25, 0.5, 0.75, 1.0 - 1e-6, 1.0 - 1e-9, 1.0};
    std::mt19937 random(26);
    std::uniform_real_distribution<double> depth01(0.0, 1.0);
    for (int k = 0; k < 2000; ++k) depths.push_back(depth01(random));
    std::sort(depths.begin(), depths.end());
    return depths;
}

double float_spacing_above(double d) {
    const float f = static_cast<float>(d);
    return double(std::nextafter(f, 2.0f)) - f;
}

}  // namespace

TEST(DepthFormat, IsDescribedByItsEncodingAndWhetherReversed) {
    EXPECT_EQ(describe(DepthFormat{}), "float32");
    EXPECT_EQ(describe(DepthFormat{.encoding = DepthEncoding::unorm16}), "unorm16");
    EXPECT_EQ(describe(DepthFormat{.encoding = DepthEncoding::unorm24, .reversed = true}), "unorm24 reversed");
    EXPECT_EQ(depth_encodings().front(), DepthEncoding::float32) << "the default first";
}

TEST(DepthFormat, AUnormStepIsOneOverItsLevelsAnywhereEitherWay) {
    for (bool reversed : {false, true})
        for (double d : {0.0, 0.001, 0.3, 0.999, 1.0}) {
            EXPECT_EQ(depth_step({.encoding = DepthEncoding::unorm16, .reversed = reversed}, d), 1.0 / 65535.0) << d;
            EXPECT_EQ(depth_step({.encoding = DepthEncoding::unorm24, .reversed = reversed}, d), 1.0 / 16777215.0) << d;
        }
}

TEST(DepthFormat, AFloat32StepIsTheSpacingOfFloatsAtTheDepth) {
    for (double d : {0.5, 0.6, 0.75, 0.99, 1.0 - 1e-7}) EXPECT_EQ(depth_step({}, d), std::ldexp(1.0, -24)) << d;
    EXPECT_EQ(depth_step({}, 0.3), std::ldexp(1.0, -25)) << "[0.25, 0.5): half as far apart";
    EXPECT_EQ(depth_step({}, 1.0), std::ldexp(1.0, -24)) << "at the top of the range, the gap below it";
    for (double d : depths_to_try())
        if (static_cast<float>(d) < 1.0f) {  // below the top of the range
            EXPECT_EQ(depth_step({}, d), float_spacing_above(d)) << d;
        }
}

// Reversed, float32's dense levels near 0 fall at the far end: there its step is the spacing at
// s = 1 − d, far below plain float32's 2^-24 (and the other way round near the light).
TEST(DepthFormat, Float32ReversedIsFineNearTheFarEndWherePlainFloat32IsCoarse) {
    const DepthFormat reversed{.reversed = true};
    for (double d : {1.0 - 1e-3, 1.0 - 1e-5, 1.0 - 1e-7}) {
        EXPECT_LT(depth_step(reversed, d), 0.01 * depth_step({}, d)) << d;
        EXPECT_EQ(depth_step(reversed, d), float_spacing_above(1.0 - d)) << d;
    }
    EXPECT_LT(depth_step({}, 1e-5), 0.01 * depth_step(reversed, 1e-5));
}

// What a format stores is one of its levels, the nearest: stored again, it stays; it never runs
// against the depth; and it lies within half a step of it.
TEST(DepthFormat, StoredDepthIsIdempotentMonotonicAndWithinHalfAStep) {
    const std::vector<double> depths = depths_to_try();
    for (const DepthFormat& format : depth_formats()) {
        double before = -1.0;
        for (double d : depths) {
            const double stored = stored_depth(format, d);
            EXPECT_EQ(stored_depth(format, stored), stored) << describe(format) << " at " << d;
            EXPECT_GE(stored, before) << describe(format) << " at " << d;
            EXPECT_LE(std::abs(stored - d), depth_step(format, d) / 2.0 + 1e-16) << describe(format) << " at " << d;
            before = stored;
        }
    }
}

// The codes order as the depths they stand for (plain) or against them (reversed), so that the
// rasterizer keeps the nearest by comparing codes; nothing drawn is d = 1 in every format.
TEST(DepthFormat, CodesOrderAsTheStoredValuesAndTheFarCodeIsDepthOne) {
    for (const DepthFormat& format : depth_formats()) {
        const DepthDecoder decode(format);
        EXPECT_EQ(decode(far_code(format)), 1.0) << describe(format);
        const DepthCode near = depth_code(format, format_value(format, 0.2));
        const DepthCode far = depth_code(format, format_value(format, 0.7));
        EXPECT_EQ(format.reversed, near > far) << describe(format);
        EXPECT_EQ(decode(near), stored_depth(format, 0.2)) << describe(format);
    }
}

// ---- The rasterizer stores each format's depth ----

namespace {

constexpr int kResolution = 32;

// Light from above over [-4, 4]²: u = x / 8 + 1/2, v = z / 8 + 1/2, d = (5 - y) / 10.
ShadowSetup overhead_setup() {
    ShadowMap map;
    map.world_to_uvz = glm::transpose(glm::dmat4(0.125, 0.0, 0.0, 0.5,  //
                                                 0.0, 0.0, 0.125, 0.5,  //
                                                 0.0, -0.1, 0.0, 0.5,   //
                                                 0.0, 0.0, 0.0, 1.0));
    return {.maps = {map}};
}

// A horizontal square [x0, x1] x [z0, z1] at height y, as object `object`, appended.
void add_square(WorldTriangles& out, double x0, double x1, double z0, double z1, double y, int object) {
    const int base = static_cast<int>(out.vertices.size());
    out.vertices.insert(out.vertices.end(), {{x0, y, z0}, {x0, y, z1}, {x1, y, z1}, {x1, y, z0}});
    out.triangles.insert(out.triangles.end(), {{base, base + 1, base + 2}, {base, base + 2, base + 3}});
    out.object.insert(out.object.end(), {object, object});
}

// The height whose depth under overhead_setup() is d.
double height_of_depth(double d) { return 5.0 - 10.0 * d; }

}  // namespace

TEST(DepthFormatRaster, APlaneStoresExactlyTheFormatsDepthOfIt) {
    const ShadowSetup setup = overhead_setup();
    WorldTriangles plane;
    add_square(plane, -2.0, 2.0, -2.0, 2.0, 1.2345, 0);
    const double d = world_to_uvz(setup.maps[0], {0.0, 1.2345, 0.0}).z;
    for (const DepthFormat& format : depth_formats()) {
        const DepthMap map = rasterize_depth(plane, {true}, setup, kResolution, format);
        EXPECT_EQ(map.format, format);
        int covered = 0;
        for (int y = 0; y < kResolution; ++y)
            for (int x = 0; x < kResolution; ++x) {
                const bool inside = x >= 8 && x < 24 && y >= 8 && y < 24;  // the square's texel centres
                ASSERT_EQ(map.at(x, y), inside ? stored_depth(format, d) : 1.0) << describe(format) << " " << x;
                covered += inside;
            }
        EXPECT_EQ(covered, 16 * 16);
        if (format.encoding != DepthEncoding::float32) {
            EXPECT_NE(stored_depth(format, d), d) << describe(format) << ": a depth between two levels, rounded";
        }
    }
}

// Two planes 0.3 of a 16-bit step apart, the nearer over one half and the farther over the other:
// unorm16 rounds both to one level (the order is lost, a receiver on either reads the other's depth
// as its own), while float32 keeps the farther one farther.
TEST(DepthFormatRaster, PlanesAFractionOfAStepApartLoseTheirOrderInUnorm16) {
    const ShadowSetup setup = overhead_setup();
    const double level = 20000.0 / 65535.0, apart = 0.3 / 65535.0;
    WorldTriangles planes;
    add_square(planes, -2.0, 0.0, -2.0, 2.0, height_of_depth(level), 0);
    add_square(planes, 0.0, 2.0, -2.0, 2.0, height_of_depth(level + apart), 0);
    const auto nearer_and_farther = [&](const DepthFormat& format) {
        const DepthMap map = rasterize_depth(planes, {true}, setup, kResolution, format);
        return std::pair{map.at(12, 16), map.at(20, 16)};  // under the nearer plane, under the farther
    };
    for (bool reversed : {false, true}) {
        const auto [near16, far16] = nearer_and_farther({.encoding = DepthEncoding::unorm16, .reversed = reversed});
        EXPECT_EQ(near16, far16) << reversed;
        EXPECT_NEAR(near16, level, 1e-12) << reversed;
        const auto [near32, far32] = nearer_and_farther({.reversed = reversed});
        EXPECT_LT(near32, far32) << reversed;
        EXPECT_NEAR(far32 - near32, apart, 1.2e-7) << reversed << ": to a float's spacing there, 2^-24 at most";
    }
}

// Where two casters overlap the nearer is kept: the least d, which reversed is the greatest stored s.
TEST(DepthFormatRaster, TheNearestCasterIsKeptInEveryFormat) {
    const ShadowSetup setup = overhead_setup();
    WorldTriangles stacked;
    add_square(stacked, -2.0, 2.0, -2.0, 2.0, height_of_depth(0.6), 0);
    add_square(stacked, -1.0, 1.0, -1.0, 1.0, height_of_depth(0.3), 0);
    for (const DepthFormat& format : depth_formats()) {
        const DepthMap map = rasterize_depth(stacked, {true}, setup, kResolution, format);
        EXPECT_EQ(map.at(16, 16), stored_depth(format, world_to_uvz(setup.maps[0], {0, height_of_depth(0.3), 0}).z))
            << describe(format);
        EXPECT_EQ(map.at(9, 9), stored_depth(format, world_to_uvz(setup.maps[0], {0, height_of_depth(0.6), 0}).z))
            << describe(format);
    }
}

// ---- What the precision does to a lookup ----

namespace {

// A ground 20 units wide that casts on itself, and a box over it, lit 20° off the vertical; the
// camera looks straight down from 30 units up.
Scene ground_and_box() {
    Scene scene;
    scene.objects.push_back({.name = "ground", .shape = Shape::plane, .size = {20.0, 1.0, 20.0}});
    scene.objects.push_back({.name = "box", .position = {0.0, 2.0, 0.0}, .size = {2.0, 2.0, 2.0}});
    scene.light.direction = glm::normalize(glm::dvec3(std::sin(glm::radians(20.0)), -std::cos(glm::radians(20.0)), 0));
    scene.camera = {.position = {0.0, 30.0, 0.0},
                    .target = {0.0, 0.0, 0.0},
                    .up = {0.0, 0.0, -1.0},
                    .fov_y_deg = 35.0,
                    .aspect = 1.0,
                    .near = 1.0,
                    .far = 100.0};
    return scene;
}

// An orthographic map along the light over the whole ground, its depth range 1e5 units deep: the
// ground lies 100 units from its near plane (d ≈ 1e-3), where a 16-bit step is 1.5 world units and
// float32's a hundred-thousandth of one.
ShadowSetup deep_orthographic_map(const Scene& scene) {
    const glm::dvec3 l = scene.light.direction;
    const glm::dmat4 view = glm::lookAt(-100.0 * l, glm::dvec3(0.0), glm::dvec3(0, 0, 1));
    const glm::dmat4 clip_from_world = glm::ortho(-15.0, 15.0, -15.0, 15.0, 0.0, 1e5) * view;
    return {.maps = {{.world_to_uvz = uvz_from_clip({}) * clip_from_world}}};
}

}  // namespace

TEST(DepthFormatLookup, A16BitMapOverADeepRangeMisclassifiesFarMoreThanFloat32) {
    const Scene scene = ground_and_box();
    const WorldTriangles triangles = tessellate(scene);
    const ReferenceImage reference = exact_reference(scene, triangles, 160, 160);
    const ShadowSetup setup = deep_orthographic_map(scene);
    const Method& focused = method_or_throw("focused");  // its lookup settings, the default bias
    const auto misclassified = [&](const std::string& depth_format, double& depth_step) {
        const ShadowLookup lookup =
            lookup_from(resolve_settings("focused", focused.settings, {{"depth_format", depth_format}}));
        const DepthMap depth = rasterize_depth(triangles, caster_flags(scene), setup, 512, lookup.format);
        const ShadowReader reader(setup, depth, scene.light, lookup);
        const ShadowError e =
            measure_shadow_error(scene, reference, reader, receiver_visibility(scene, reference, reader));
        EXPECT_GT(e.receiver_pixels, 160u * 160u / 2) << depth_format;
        depth_step = e.depth_step.mean;
        return e.misclassified;
    };
    double step16 = 0.0, step32 = 0.0;
    const double unorm16 = misclassified("unorm16", step16), float32 = misclassified("float32", step32);
    std::printf("deep orthographic map: unorm16 misclassifies %.2f%% (step %.3g world units), float32 %.3f%% (%.3g)\n",
                100 * unorm16, step16, 100 * float32, step32);
    EXPECT_NEAR(step16, 1e5 / 65535.0, 1e-6) << "one 16-bit step along the light";
    EXPECT_LT(step32, 1e-4);
    EXPECT_LT(float32, 0.01);
    EXPECT_GT(unorm16, 10.0 * float32 + 0.1) << "acne where rounding drops the ground's depth below the bias";
}
