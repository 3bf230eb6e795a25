// The one CPU lookup of a shadow setup (core/maps): selection rules, tiles of an atlas, the
// paraboloid's closed form, and the rasterizer drawing each map into its own tile only.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "maps/map_lookup.hpp"
#include "raster/depth_map.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

// An orthographic map looking straight down (-y) at [-h, h]² in x, z (u = x / 2h + 1/2, v = z / 2h
// + 1/2), depth 0.75 - y / 4: 0 at y = 3, 1 at y = -1.
ShadowMap overhead(const glm::dvec4& viewport = {0, 0, 1, 1}, double h = 4.0) {
    ShadowMap map;
    map.world_to_uvz = glm::dmat4(glm::dvec4(1 / (2 * h), 0, 0, 0), glm::dvec4(0, 0, -1 / 4.0, 0),
                                  glm::dvec4(0, 1 / (2 * h), 0, 0), glm::dvec4(0.5, 0.5, 0.75, 1));
    map.viewport = viewport;
    return map;
}

// A square caster at height 1 over [-1, 1]², two triangles.
WorldTriangles caster() {
    WorldTriangles t;
    t.vertices = {{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}};
    t.triangles = {{0, 1, 2}, {0, 2, 3}};
    t.object = {0, 0};
    return t;
}

ShadowMap paraboloid_map(const glm::dmat3& frame, const glm::dvec4& viewport = {0, 0, 1, 1}) {
    ShadowMap map;
    map.projection = Projection::paraboloid;
    map.paraboloid = {.centre = {0, 5, 0}, .frame_from_world = frame, .near = 1.0, .far = 11.0};
    map.viewport = viewport;
    map.z_bias_scale = 1.0 / 10.0;
    return map;
}

// The frame looking down -y (the hemisphere's +z is world -y), and its opposite.
// (GLM's constructor takes columns: q = (x, z, -y) and q = (-x, z, y).)
const glm::dmat3 kDown(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0));
const glm::dmat3 kUp(glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, 1, 0));

}  // namespace

TEST(MapLookup, OneLinearMapIsTheMatrixDividedByW) {
    const ShadowSetup setup{.maps = {overhead()}};
    const std::optional<MapLookup> at = look_up(setup, {2, 0, -2}, 0.0);
    ASSERT_TRUE(at);
    EXPECT_EQ(at->map, 0);
    EXPECT_NEAR(at->uv.x, 0.75, 1e-12);
    EXPECT_NEAR(at->uv.y, 0.25, 1e-12);
    EXPECT_NEAR(at->depth, 0.75, 1e-12);
    // The bias moves the depth toward the light by z_bias_scale per world unit, before the division.
    EXPECT_NEAR(look_up(setup, {2, 0, -2}, 0.4)->depth, 0.75 - 0.4, 1e-12);
    EXPECT_FALSE(look_up(setup, {5, 0, 0}, 0.0)) << "off the map: lit";
}

TEST(MapLookup, ViewDepthPicksTheSplitAndTheLastSplitIsClosed) {
    ShadowSetup setup{.maps = {overhead({0, 0, 0.5, 0.5}), overhead({0.5, 0, 1, 0.5})}};
    setup.selection = {.rule = MapSelection::Rule::view_depth,
                       .eye = {0, 0, 4},
                       .view_axis = {0, 0, -1},
                       .split_depths = {0.0, 3.0, 8.0}};
    EXPECT_EQ(select_map(setup, {0, 0, 3.5}), 0);   // depth 0.5
    EXPECT_EQ(select_map(setup, {0, 0, 1.0}), 1);   // depth 3: the second split's start
    EXPECT_EQ(select_map(setup, {0, 0, -4.0}), 1);  // depth 8: the far end belongs to the last split
    EXPECT_EQ(select_map(setup, {0, 0, -4.5}), -1);
    EXPECT_EQ(select_map(setup, {0, 0, 5.0}), -1);  // behind the eye
}

TEST(MapLookup, TileBoundsPickTheFirstMapHoldingThePoint) {
    ShadowSetup setup{.maps = {overhead({0, 0, 0.5, 0.5}, 2.0), overhead({0.5, 0, 1, 0.5}, 4.0)}};
    setup.selection.rule = MapSelection::Rule::tile_bounds;
    EXPECT_EQ(select_map(setup, {0, 0, 0}), 0);
    EXPECT_EQ(select_map(setup, {3.5, 0, 0}), 1);
    EXPECT_EQ(select_map(setup, {9, 0, 0}), -1);
}

// The face_axis rule over a cube's axes (+x, -x, +y, -y, +z, -z) is the major axis, x before y
// before z on ties, as a GPU's cube map picks.
TEST(MapLookup, CubeFacesByTheMajorAxis) {
    ShadowSetup setup;
    setup.selection = {.rule = MapSelection::Rule::face_axis, .centre = {1, 2, 3}};
    for (int face = 0; face < 6; ++face) {
        ShadowMap m;
        m.projection = Projection::cube_face;
        m.cube_face = face;
        m.face_axis[face / 2] = face % 2 == 0 ? 1.0 : -1.0;
        setup.maps.push_back(m);
    }
    EXPECT_EQ(select_map(setup, {2, 3, 3}), 0);  // ties: x before y
    EXPECT_EQ(select_map(setup, {1, 1, 2}), 3);  // y before z
    EXPECT_EQ(select_map(setup, {5, 2, 3}), 0);
    EXPECT_EQ(select_map(setup, {-5, 2, 3}), 1);
    EXPECT_EQ(select_map(setup, {1, 2.5, 3}), 2);
    EXPECT_EQ(select_map(setup, {1, 0, 2.5}), 3);
    EXPECT_EQ(select_map(setup, {1.1, 2, 9}), 4);
    EXPECT_EQ(select_map(setup, {1, 2.2, -9}), 5);
}

// Brabec et al.: a direction d maps to (d.x, d.y) / (1 + d.z); depth is the distance, linear.
TEST(MapLookup, ParaboloidClosedForm) {
    const ShadowMap down = paraboloid_map(kDown);
    EXPECT_NEAR(glm::length(glm::dvec2(world_to_uvz(down, {0, -5, 0})) - glm::dvec2(0.5)), 0.0, 1e-12);
    EXPECT_NEAR(world_to_uvz(down, {0, -5, 0}).z, (10.0 - 1.0) / 10.0, 1e-12);
    // At 90° from the axis (the hemisphere's rim) |(u, v) - centre| = 1/2: the disc's edge.
    const glm::dvec3 rim = world_to_uvz(down, {3, 5, 0});
    EXPECT_NEAR(glm::length(glm::dvec2(rim) - glm::dvec2(0.5)), 0.5, 1e-12);
    EXPECT_NEAR(rim.z, 0.2, 1e-12);
    // 45°: tan(22.5°) = √2 - 1 from the centre, in the half-disc's units.
    const glm::dvec3 diagonal = world_to_uvz(down, {2, 3, 0});
    EXPECT_NEAR(2.0 * (diagonal.x - 0.5), std::sqrt(2.0) - 1.0, 1e-12);
    // Depth grows along a ray from the light, u and v stay.
    const glm::dvec3 a = world_to_uvz(down, {1, 3, 1}), b = world_to_uvz(down, {2, 1, 2});
    EXPECT_GT(b.z, a.z);
    EXPECT_NEAR(a.x, b.x, 1e-12);
    EXPECT_NEAR(a.y, b.y, 1e-12);
    EXPECT_NEAR(world_per_depth_unit(down, glm::normalize(glm::dvec3(1, -2, 1)), {1, 3, 1}), 10.0, 1e-9);
}

TEST(MapLookup, HemispheresSplitSpaceAtTheirPlane) {
    ShadowSetup setup{.maps = {paraboloid_map(kDown, {0, 0, 0.5, 0.5}), paraboloid_map(kUp, {0.5, 0, 1, 0.5})}};
    setup.selection.rule = MapSelection::Rule::hemisphere;
    EXPECT_EQ(select_map(setup, {0.3, 0, 0.1}), 0);
    EXPECT_EQ(select_map(setup, {0.3, 9, 0.1}), 1);
    const std::optional<MapLookup> above = look_up(setup, {0, 9, 0}, 0.0);
    ASSERT_TRUE(above);
    EXPECT_NEAR(above->uv.x, 0.5, 1e-12);
    EXPECT_NEAR(above->depth, 0.3, 1e-12);
}

TEST(MapLookup, TexelsStayInTheirTile) {
    const ShadowMap right = overhead({0.5, 0.0, 1.0, 0.5});
    EXPECT_DOUBLE_EQ(tile_resolution(right, 64), 32.0);
    EXPECT_EQ(texel_of(right, {0.0, 0.0}, 64), glm::ivec2(32, 0));
    EXPECT_EQ(texel_of(right, {1.0, 1.0}, 64), glm::ivec2(63, 31));  // u = v = 1: the tile's last texel
    EXPECT_EQ(texel_of(right, {0.5, 0.5}, 64), glm::ivec2(48, 16));
}

// Two maps of one caster, each in its tile: each tile holds the map's own picture, the rest of the
// texture stays empty, and the lookup of each map reads its own tile.
TEST(AtlasRaster, EachMapIsDrawnIntoItsTileOnly) {
    constexpr int n = 64;
    const ShadowSetup single{.maps = {overhead()}};
    ShadowSetup atlas{.maps = {overhead({0, 0, 0.5, 0.5}), overhead({0.5, 0.5, 1, 1})}};
    const DepthMap whole = rasterize_depth(caster(), {true}, single, n / 2);
    const DepthMap tiles = rasterize_depth(caster(), {true}, atlas, n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const bool first = x < n / 2 && y < n / 2, second = x >= n / 2 && y >= n / 2;
            const float expected = first ? whole.at(x, y) : second ? whole.at(x - n / 2, y - n / 2) : 1.0f;
            ASSERT_EQ(tiles.at(x, y), expected) << x << ", " << y;
        }
    atlas.selection.rule = MapSelection::Rule::tile_bounds;
    EXPECT_TRUE(in_shadow(tiles, atlas, {0.5, 0.0, 0.5}, 0.0));
    EXPECT_FALSE(in_shadow(tiles, atlas, {3.0, 0.0, 0.5}, 0.0));
}

// The paraboloid rasterized as a GPU draws it: the caster below the light lands in the lower
// hemisphere's tile, around its centre, and nothing of it in the upper one.
TEST(AtlasRaster, ParaboloidHemispheresClipAtTheirPlane) {
    constexpr int n = 64;
    ShadowSetup setup{.maps = {paraboloid_map(kDown, {0, 0, 0.5, 0.5}), paraboloid_map(kUp, {0.5, 0, 1, 0.5})}};
    setup.selection.rule = MapSelection::Rule::hemisphere;
    const DepthMap depth = rasterize_depth(caster(), {true}, setup, n);
    // Straight edges, depth interpolated between the corners (each sqrt(18) from the light).
    EXPECT_NEAR(depth.at(16, 16), (std::sqrt(18.0) - 1.0) / 10.0, 1e-6);
    for (int y = 0; y < n / 2; ++y)
        for (int x = n / 2; x < n; ++x) ASSERT_EQ(depth.at(x, y), 1.0f) << "the upper hemisphere sees nothing";
    const Light lamp{.type = LightType::point, .position = {0, 5, 0}};
    EXPECT_TRUE(in_shadow(depth, setup, {0.2, -3.0, 0.1}, 0.05, lamp));
    EXPECT_FALSE(in_shadow(depth, setup, {0.2, 2.0, 0.1}, 0.05, lamp)) << "between the light and the caster";
}

namespace {

// Two overhead maps of one caster side by side, chosen by view depth along +x: the fine map 0 (h =
// 2) serves x in [-1.5, 1.5), the coarse map 1 (h = 8) x in [1.5, 10].
ShadowSetup fine_then_coarse(double blend_band) {
    ShadowSetup setup{.maps = {overhead({0, 0, 0.5, 0.5}, 2.0), overhead({0.5, 0, 1, 0.5}, 8.0)}};
    setup.selection = {.rule = MapSelection::Rule::view_depth,
                       .eye = {0, 0, 0},
                       .view_axis = {1, 0, 0},
                       .split_depths = {-1.5, 1.5, 10.0},
                       .blend_band = blend_band};
    return setup;
}

// A caster at height 1 over x in [-9, 9], z in [-9, 0.3]: its shadow's edge on the ground runs along
// x, across the boundary between the maps, at z = 0.3, which falls inside a texel row of either map.
WorldTriangles half_plane_caster() {
    WorldTriangles t;
    t.vertices = {{-9, 1, -9}, {9, 1, -9}, {9, 1, 0.3}, {-9, 1, 0.3}};
    t.triangles = {{0, 1, 2}, {0, 2, 3}};
    t.object = {0, 0};
    return t;
}

}  // namespace

// The band is the last blend_band of a split: the weight rises linearly from its start to 1 at the
// split's far end; the last split and the other rules never blend.
TEST(MapBlend, WeightRisesLinearlyOverTheLastShareOfTheSplit) {
    const ShadowSetup setup = fine_then_coarse(0.25);  // split 0 is 3 deep: a band of 0.75 from x = 0.75
    EXPECT_EQ(blend_of(setup, {0.5, 0, 0}).next, -1);
    EXPECT_EQ(blend_of(setup, {0.75, 0, 0}).next, -1) << "the band's start: weight 0";
    const MapBlend inside = blend_of(setup, {1.2, 0, 0});
    EXPECT_EQ(inside.map, 0);
    EXPECT_EQ(inside.next, 1);
    EXPECT_NEAR(inside.weight, 0.6, 1e-12);
    EXPECT_NEAR(blend_of(setup, {1.5 - 1e-9, 0, 0}).weight, 1.0, 1e-8);
    const MapBlend last = blend_of(setup, {9.9, 0, 0});
    EXPECT_EQ(last.map, 1);
    EXPECT_EQ(last.next, -1) << "the last split fades into nothing";
    EXPECT_EQ(blend_of(fine_then_coarse(0.0), {1.4, 0, 0}).next, -1) << "no band: a hard seam";
    ShadowSetup tiles = setup;
    tiles.selection.rule = MapSelection::Rule::tile_bounds;
    EXPECT_EQ(blend_of(tiles, {1.4, 0, 0}).next, -1);
}

// In the band the visibility is the crossfade of the two maps' verdicts, and a pixel is shadowed
// below one half of it.
TEST(MapBlend, AmountCrossfadesTheTwoVerdicts) {
    const ShadowSetup setup = fine_then_coarse(0.5);  // band from x = 0
    const DepthMap depth = rasterize_depth(half_plane_caster(), {true}, setup, 64);
    DepthMap only_map_0_sees_it = depth;  // map 1's tile (the texture's right half, top) emptied
    for (int y = 0; y < 32; ++y)
        for (int x = 32; x < 64; ++x) only_map_0_sees_it.set(x, y, 1.0);
    for (double x : {-0.5, 0.3, 0.75, 1.2}) {
        const glm::dvec3 p(x, 0, -1);
        const double w = blend_of(setup, p).weight;
        EXPECT_NEAR(constant_bias_visibility(only_map_0_sees_it, setup, p, 0.01), w, 1e-12) << x;
        EXPECT_EQ(in_shadow(only_map_0_sees_it, setup, p, 0.01), w < 0.5) << x;
        EXPECT_EQ(constant_bias_visibility(depth, setup, p, 0.01), 0.0) << "both maps see the caster";
    }
}

// The seam: the shadow's edge lies where each map's texel rows put it, so between the two positions
// the verdict jumps from lit to shadowed where the maps change. With the band it ramps over the band.
TEST(MapBlend, TheBandRemovesTheSeamStep) {
    constexpr double step = 0.01;
    const auto largest_step = [&](double blend_band) {
        const ShadowSetup setup = fine_then_coarse(blend_band);
        const DepthMap depth = rasterize_depth(half_plane_caster(), {true}, setup, 64);
        double largest = 0.0;
        for (double z = 0.0; z <= 0.6; z += 0.02) {  // lines along x across the boundary, near the shadow's edge
            double before = constant_bias_visibility(depth, setup, {-1.0, 0, z}, 0.01);
            for (double x = -1.0 + step; x <= 3.0; x += step) {
                const double amount = constant_bias_visibility(depth, setup, {x, 0, z}, 0.01);
                largest = std::max(largest, std::abs(amount - before));
                before = amount;
            }
        }
        return largest;
    };
    const double hard = largest_step(0.0), blended = largest_step(0.3);
    std::cout << "largest change of the shadow amount between samples " << step << " apart: " << hard
              << " without a band, " << blended << " with a band of 0.3\n";
    EXPECT_EQ(hard, 1.0) << "the maps put the edge in different places: a seam";
    // A linear ramp over the band (0.3 of a split 3 deep): step / 0.9 per sample.
    EXPECT_LE(blended, step / 0.9 * 1.001);
}
