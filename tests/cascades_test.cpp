// Cascaded shadow maps: PSSM's split formula in closed form, the atlas, the stabilization's promises
// (whole-texel moves under translation, a fixed texel size under rotation), every visible receiver in
// its cascade's tile, and bad settings refused by name.
#include <gtest/gtest.h>

#include <random>

#include "math/matrix.hpp"
#include "methods/cascade_atlas.hpp"
#include "methods/cascade_splits.hpp"
#include "methods/cascades.hpp"
#include "metrics/measurement.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

ShadowSetup cascades(const ShadowInputs& in, const std::map<std::string, std::string>& set = {}) {
    return compute_cascades(in, resolve_settings("cascades", cascades_settings(), set), nullptr);
}

ShadowInputs default_inputs() { return gather_inputs(load_scene(source_path("data/scenes/default.json"))); }

// The same scene seen from a camera moved by `offset`, or turned to look along `direction`.
ShadowInputs moved(const Scene& scene, const glm::dvec3& offset) {
    Scene s = scene;
    s.camera.position += offset;
    s.camera.target += offset;
    return gather_inputs(s);
}

ShadowInputs turned(const Scene& scene, const glm::dvec3& direction) {
    Scene s = scene;
    s.camera.target = s.camera.position + direction;
    return gather_inputs(s);
}

// How many of a map's tile texels a world point lies from the tile's texel grid, per axis.
glm::dvec2 texel_offset(const ShadowMap& map, const glm::dvec3& world, int texture_resolution) {
    const glm::dvec2 texels = glm::dvec2(world_to_uvz(map, world)) * tile_resolution(map, texture_resolution);
    return glm::abs(texels - glm::round(texels));
}

// The map's u and v per world unit (the texel size, up to the resolution) agree to rounding.
bool same_texel_size(const ShadowMap& a, const ShadowMap& b) {
    for (int axis = 0; axis < 2; ++axis) {
        const double per_world_a = glm::length(glm::dvec3(row(a.world_to_uvz, axis)));
        const double per_world_b = glm::length(glm::dvec3(row(b.world_to_uvz, axis)));
        if (std::abs(per_world_a - per_world_b) > 1e-12 * per_world_a) return false;
    }
    return true;
}

}  // namespace

TEST(CascadeSplits, PracticalSchemeMatchesPssmsClosedForm) {
    const std::vector<double> half = practical_splits(1.0, 1000.0, 4, 0.5);
    ASSERT_EQ(half.size(), 5u);
    EXPECT_EQ(half.front(), 1.0);
    EXPECT_EQ(half.back(), 1000.0);
    EXPECT_NEAR(half[1], 128.19, 0.005);
    EXPECT_NEAR(half[2], 266.06, 0.005);
    EXPECT_NEAR(half[3], 464.04, 0.005);
    // λ = 1: every split the same ratio, 1000^(1/4) = 5.623.
    const std::vector<double> logarithmic = practical_splits(1.0, 1000.0, 4, 1.0);
    EXPECT_NEAR(logarithmic[1], 5.623, 0.0005);
    EXPECT_NEAR(logarithmic[2], 31.62, 0.005);
    EXPECT_NEAR(logarithmic[3], 177.8, 0.05);
    // λ = 0: uniform steps of 999 / 4.
    const std::vector<double> uniform = practical_splits(1.0, 1000.0, 4, 0.0);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(uniform[i + 1] - uniform[i], 249.75, 1e-9);
}

TEST(CascadeSplits, ManualFractionsOfTheDepthRange) {
    EXPECT_EQ(manual_splits(1.0, 101.0, {0.05, 0.2, 0.5}), (std::vector<double>{1.0, 6.0, 21.0, 51.0, 101.0}));
}

TEST(CascadeAtlas, TwoByTwoTileMatrixScalesByAQuarter) {
    const std::vector<AtlasTile> tiles = atlas_layout(4, {});
    for (int tile = 0; tile < 4; ++tile) {
        const glm::dmat4 m = atlas_tile_matrix(tiles[tile]);
        EXPECT_EQ(m[0][0], 0.25);
        EXPECT_EQ(m[1][1], -0.25);
        EXPECT_EQ(m[3][0], 0.25 + 0.5 * (tile % 2));
        EXPECT_EQ(m[3][1], 0.25 + 0.5 * (tile / 2));
    }
}

// Any count, any mix of sides: tiles inside the texture, on whole texels of a 512² atlas, none
// overlapping, each as large as the texture allows (the largest can't double: the areas would pass 1).
TEST(CascadeAtlas, TilesOfAnySidesFitWithoutOverlapAndAsLargeAsTheyCan) {
    std::vector<std::pair<int, std::vector<double>>> layouts;  // count, sides
    for (int count = 1; count <= kMaxCascades; ++count) layouts.push_back({count, {}});
    layouts.push_back({4, {1, 0.5, 0.5, 0.5}});
    layouts.push_back({5, {0.25, 1, 0.5, 0.125, 0.5}});
    layouts.push_back({8, {1, 1, 0.5, 0.5, 0.25, 0.25, 0.125, 0.125}});
    std::mt19937 rng(3);
    for (int k = 0; k < 200; ++k) {
        std::vector<double> sides(1 + rng() % kMaxCascades);
        for (double& side : sides) side = std::exp2(-double(rng() % 4));
        layouts.push_back({int(sides.size()), sides});
    }
    for (const auto& [n, sides] : layouts) {
        const std::vector<AtlasTile> tiles = atlas_layout(n, sides);
        ASSERT_EQ(int(tiles.size()), n);
        double area = 0.0;
        for (int i = 0; i < n; ++i) {
            const glm::dvec4 a = tile_viewport(tiles[i]);
            EXPECT_TRUE(a.x >= 0 && a.y >= 0 && a.z <= 1 && a.w <= 1) << n << " tile " << i;
            EXPECT_EQ(a * 512.0, glm::round(a * 512.0)) << "tile edges on texel boundaries";
            if (!sides.empty()) {
                EXPECT_EQ(tiles[i].side / tiles[0].side, sides[i] / sides[0]) << "the sides asked for";
            }
            for (int j = 0; j < i; ++j) {
                const glm::dvec4 b = tile_viewport(tiles[j]);
                EXPECT_TRUE(a.x >= b.z || b.x >= a.z || a.y >= b.w || b.y >= a.w) << n << ": tiles " << i << ", " << j;
            }
            area += tiles[i].side * tiles[i].side;
        }
        EXPECT_GT(4 * area, 1.0) << "at twice the side they would not fit";
    }
}

TEST(CascadeAtlas, ANearCascadeTwiceTheSideGetsFourTimesTheTexels) {
    const std::vector<AtlasTile> tiles = atlas_layout(4, {1, 0.5, 0.5, 0.5});
    EXPECT_EQ(tiles[0].side, 0.5);
    for (int i = 1; i < 4; ++i) EXPECT_EQ(tiles[i].side, 0.25);
}

// The map reads the texel grid through the light space's origin, the scene's centre: after any camera
// translation that centre still lies on a texel corner of every cascade's tile, and any other world
// point keeps its place within its texel (the whole map moved by whole texels).
TEST(Cascades, StabilizedMapsMoveByWholeTexelsForAnyTranslation) {
    const Scene scene = load_scene(source_path("data/scenes/default.json"));
    const glm::dvec3 anchor = default_inputs().scene_bounds.center();
    const auto within_texel = [](const ShadowMap& map, const glm::dvec3& world, int resolution) {
        const glm::dvec2 texels = glm::dvec2(world_to_uvz(map, world)) * tile_resolution(map, resolution);
        return texels - glm::floor(texels);
    };
    const std::vector<glm::dvec3> points{{3.7, 0.2, -5.1}, {-12.25, 1.5, 8.8}, {0.0, 0.0, 0.0}};
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> offset(-30.0, 30.0);
    for (const char* fit : {"cascade", "scene", "sphere"}) {
        const ShadowSetup home = cascades(default_inputs(), {{"stabilize", "on"}, {"fit", fit}});
        int compared = 0;  // maps of the same texel size as at home, whose texel phases must agree
        for (int k = 0; k < 20; ++k) {
            const ShadowInputs in = moved(scene, {offset(rng), 0.1 * offset(rng), offset(rng)});
            const ShadowSetup setup = cascades(in, {{"stabilize", "on"}, {"fit", fit}});
            ASSERT_EQ(setup.maps.size(), 4u);
            for (size_t i = 0; i < setup.maps.size(); ++i)
                for (int resolution : {512, 2048, 8192}) {
                    const glm::dvec2 off = texel_offset(setup.maps[i], anchor, resolution);
                    EXPECT_LT(std::max(off.x, off.y), 1e-6) << fit << " at " << resolution;
                    if (!same_texel_size(setup.maps[i], home.maps[i])) continue;  // a box of another size: another grid
                    ++compared;
                    for (const glm::dvec3& p : points) {
                        const glm::dvec2 phase =
                            within_texel(setup.maps[i], p, resolution) - within_texel(home.maps[i], p, resolution);
                        EXPECT_LT(glm::length(phase - glm::round(phase)), 1e-6) << fit << " cascade " << i + 1;
                    }
                }
        }
        // A sphere's size does not change with the camera; the boxes' sizes do, a third of them stay (today 78 and 63).
        if (std::string(fit) == "sphere") {
            EXPECT_EQ(compared, 240);
        }
        EXPECT_GT(compared, 40) << fit;
    }
}

// The sphere's size depends on the slice alone: the texel size (u per world unit) stays the same
// however the camera turns (to rounding: the box's corner moves, its extent is recomputed from it).
TEST(Cascades, SphereFitKeepsTheTexelSizeUnderAnyRotation) {
    const Scene scene = load_scene(source_path("data/scenes/default.json"));
    const ShadowSetup first = cascades(gather_inputs(scene), {{"stabilize", "on"}, {"fit", "sphere"}});
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> azimuth(0.0, 6.283), elevation(-1.2, 0.3);
    for (int k = 0; k < 30; ++k) {
        const double a = azimuth(rng), e = elevation(rng);
        const ShadowInputs in = turned(scene, {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)});
        const ShadowSetup setup = cascades(in, {{"stabilize", "on"}, {"fit", "sphere"}});
        for (size_t i = 0; i < setup.maps.size(); ++i)
            EXPECT_TRUE(same_texel_size(setup.maps[i], first.maps[i])) << "cascade " << i + 1;
    }
}

// Every receiver corner the camera sees reads its own cascade's map (by view depth: the split that
// holds its depth) and lands in [0,1]^3 there, so in that map's tile; in the blend band also in the
// next map, which it crossfades into.
TEST(Cascades, EveryVisibleReceiverPointMapsIntoItsCascadesTile) {
    const std::vector<std::map<std::string, std::string>> variants{
        {},
        {{"count", "1"}},
        {{"count", "8"}, {"lambda", "1"}},
        {{"scheme", "manual"}, {"splits", "0.1,0.3,0.6"}},
        {{"fit", "scene"}},
        {{"fit", "sphere"}, {"stabilize", "on"}},
        {{"stabilize", "on"}},
        {{"warp", "lispsm"}},
        {{"blend", "0.3"}, {"count", "3"}},
        {{"select", "tile"}, {"fit", "sphere"}},
    };
    for (const std::string& file : shipped_scenes()) {
        const ShadowInputs in = gather_inputs(load_scene(file));
        if (!in.light.is_directional()) continue;
        const double tol = 1e-7 * in.scene_bounds.diagonal();
        for (const auto& set : variants) {
            const ShadowSetup setup = cascades(in, set);
            const MapSelection& selection = setup.selection;
            for (const glm::dvec3& p : in.receiver_points()) {
                if (!in.frustum.contains(p, -tol)) continue;
                const int i = select_map(setup, p);
                ASSERT_GE(i, 0) << file;
                ASSERT_TRUE(in_unit_cube(world_to_uvz(setup.maps[i], p), 1e-6)) << file << " map " << i;
                if (selection.rule != MapSelection::Rule::view_depth) continue;
                const double depth = glm::dot(p - selection.eye, selection.view_axis);
                EXPECT_GE(depth, selection.split_depths[i]);
                EXPECT_LE(depth, selection.split_depths[i + 1]);
                const double band = selection.blend_band * (selection.split_depths[i + 1] - selection.split_depths[i]);
                if (i + 1 < int(setup.maps.size()) && depth >= selection.split_depths[i + 1] - band) {
                    EXPECT_TRUE(in_unit_cube(world_to_uvz(setup.maps[i + 1], p), 1e-6))
                        << file << " blend into " << i + 1;
                }
            }
        }
    }
}

TEST(Cascades, BadSettingsAreRefusedWithTheirNames) {
    const ShadowInputs in = default_inputs();
    const auto refusal = [&](const std::map<std::string, std::string>& set) -> std::string {
        try {
            cascades(in, set);
        } catch (const std::invalid_argument& e) {
            return e.what();
        }
        return "accepted";
    };
    const std::vector<std::pair<std::map<std::string, std::string>, std::string>> cases{
        {{{"lambda", "1.5"}}, "lambda"},
        {{{"lambda", "-0.1"}}, "lambda"},
        {{{"count", "9"}}, "count"},
        {{{"count", "0"}}, "count"},
        {{{"count", "2.5"}}, "count"},
        {{{"scheme", "manual"}, {"splits", "0.5,0.2,0.7"}}, "splits"},
        {{{"scheme", "manual"}, {"splits", "0.2,0.2,0.7"}}, "splits"},
        {{{"scheme", "manual"}, {"splits", "0.2,0.5"}}, "splits"},
        {{{"scheme", "manual"}, {"splits", "0.2,x,0.5"}}, "splits"},
        {{{"far", "0.01"}}, "far"},
        {{{"blend", "0.6"}}, "blend"},
        {{{"fit", "tight"}}, "fit"},
        {{{"warp", "lispsm"}, {"stabilize", "on"}}, "stabilize"},
        {{{"warp", "lispsm"}, {"select", "tile"}}, "select"},
        {{{"tiles", "1,0.5"}}, "tiles"},
        {{{"tiles", "1,0.3,0.5,0.5"}}, "tiles"},
        {{{"tiles", "2,1,1,1"}}, "tiles"},
        {{{"count", "8"}, {"tiles", "1,1,1,1,1,1,1,0.125"}}, "tiles"},  // the last would be 1/32 of the atlas
    };
    for (const auto& [set, name] : cases) {
        const std::string message = refusal(set);
        EXPECT_NE(message.find("cascades"), std::string::npos) << message;
        EXPECT_NE(message.find("setting " + name + "="), std::string::npos) << name << ": " << message;
    }
}

TEST(Cascades, ASpotLightTakesTheFocusedMapAsANamedFallback) {
    const ShadowInputs in = gather_inputs(load_scene(source_path("data/scenes/spot.json")));
    const ShadowSetup setup = cascades(in);
    ASSERT_FALSE(setup.fallbacks.empty());
    EXPECT_EQ(setup.fallbacks[0].kind, NoteKind::not_directional);
    EXPECT_EQ(setup.maps.size(), 1u);
}

TEST(Cascades, NearerCascadesSpendTheirTexelsOnLessGround) {
    const ShadowSetup setup = cascades(default_inputs());
    const auto ground_per_u = [](const ShadowMap& map) {
        return 1.0 / glm::length(glm::dvec3(row(map.world_to_uvz, 0)));
    };
    for (size_t i = 1; i < setup.maps.size(); ++i)
        EXPECT_LT(ground_per_u(setup.maps[i - 1]), ground_per_u(setup.maps[i]));
}

// One output step per map (output-0 ...), and the traced maps are the untraced ones.
TEST(Cascades, TheTraceRecordsEveryMapAndChangesNone) {
    const ShadowInputs in = default_inputs();
    Trace trace;
    const Settings settings = resolve_settings("cascades", cascades_settings(), {{"warp", "lispsm"}});
    const ShadowSetup traced = compute_cascades(in, settings, &trace), plain = compute_cascades(in, settings, nullptr);
    ASSERT_EQ(traced.maps.size(), plain.maps.size());
    for (size_t i = 0; i < plain.maps.size(); ++i) {
        EXPECT_EQ(traced.maps[i].world_to_uvz, plain.maps[i].world_to_uvz);
        EXPECT_NE(trace.find("output-" + std::to_string(i)), nullptr);
        EXPECT_NE(trace.find("cascade-" + std::to_string(i + 1) + "-tile"), nullptr);  // cascades count from 1
    }
}

// The resolution per cascade, measured: a cascade given half the tile side has twice the
// perspective aliasing m (texels per pixel halve) on the same pixels; the others keep theirs.
TEST(Cascades, HalvingACascadesTileDoublesItsMeasuredAliasing) {
    const MeasureContext context = prepare_measurement(load_scene(source_path("data/scenes/default.json")), 480, 270);
    const Method& method = method_or_throw("cascades");
    const auto per_map = [&](const std::string& tiles) {
        const Settings s = resolve_settings("cascades", method.settings, {{"tiles", tiles}});
        return measure(context, method, s, 2048, -1.0).by_map->maps;
    };
    const std::vector<MapShare> equal = per_map("1,1,1,1"), halved = per_map("1,1,0.5,1");
    for (size_t i = 0; i < equal.size(); ++i) {
        ASSERT_GT(equal[i].pixels, 0u);
        EXPECT_EQ(halved[i].pixels, equal[i].pixels);
        const double ratio = halved[i].m_perspective.mean / equal[i].m_perspective.mean;
        EXPECT_NEAR(ratio, i == 2 ? 2.0 : 1.0, 1e-6) << "cascade " << i + 1;
    }
}
