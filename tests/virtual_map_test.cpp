// Virtual shadow maps: the level a footprint marks, the budget, the page table's reads, the
// aliasing it reaches and what its page cache saves along a camera path.
#include <gtest/gtest.h>

#include <cmath>

#include "exchange/inspection_json.hpp"
#include "maps/map_lookup.hpp"
#include "lookup/shadow_reader.hpp"
#include "methods/page_marking.hpp"
#include "metrics/pixel_cause.hpp"
#include "methods/virtual_map.hpp"
#include "metrics/shimmer.hpp"
#include "raster/depth_map.hpp"
#include "reference/visible_depths.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

const Method& virtual_method() { return method_or_throw("virtual"); }

ShadowSetup run_virtual(const ShadowInputs& in, std::map<std::string, std::string> set = {}) {
    return compute_virtual(in, resolve_settings("virtual", virtual_method().settings, set), nullptr);
}

// The scene's inputs with the camera's depth image traced at 320 x 180 and a texture of `resolution`.
ShadowInputs seen_inputs(const Scene& scene, int resolution) {
    ShadowInputs in = gather_inputs(scene);
    in.texture_resolution = resolution;
    trace_depth_image(in, scene, tessellate(scene), 320, 180);
    return in;
}

Scene default_scene() { return load_scene(source_path("data/scenes/default.json")); }

// A sun straight down on a 100-wide square seen from 20 above with a square 60° camera: every point
// of the plane lies at view depth 20.
ShadowInputs plane_seen_from_above(int image_height, int points_per_side) {
    ShadowInputs in;
    in.camera = camera_20_units_above_the_origin();
    in.light.type = LightType::directional;
    in.light.direction = {0, -1, 0};
    in.scene_bounds = Aabb{{-50, -1, -50}, {50, 1, 50}};
    in.texture_resolution = 4096;
    SeenReceivers seen{.image_height = image_height};
    for (int i = 0; i < points_per_side; ++i)
        for (int j = 0; j < points_per_side; ++j)
            seen.points.push_back(
                {-5.0 + 10.0 * i / (points_per_side - 1), 0.0, -5.0 + 10.0 * j / (points_per_side - 1)});
    in.seen_receivers = seen;
    return in;
}

}  // namespace

// A pixel at view depth D is 2 D tan(30°) / H wide; level 0's texel is 2 r0 R / 16384 (R the
// scene's bounding radius); the level marked is floor(log2(footprint / texel0) + bias).
TEST(Virtual, APlaneAtAKnownDistanceMarksTheLevelTheClosedFormGives) {
    const int image_height = 300;
    const ShadowInputs in = plane_seen_from_above(image_height, 21);
    const double footprint = 2.0 * 20.0 * std::tan(glm::radians(30.0)) / image_height;
    const double radius = 0.5 * in.scene_bounds.diagonal(), texel0 = 2.0 * radius / 64.0 / 16384.0;
    for (double bias : {0.0, 1.0, -1.0}) {
        const int expected = int(std::floor(std::log2(footprint / texel0) + bias));
        ASSERT_GE(expected, 0);
        const ShadowSetup setup = run_virtual(in, {{"resolution_bias", std::to_string(bias)}});
        ASSERT_EQ(setup.selection.rule, MapSelection::Rule::pages);
        const PageTable& table = setup.selection.pages;
        ASSERT_FALSE(table.pages.empty());
        for (const PageAddress& a : table.pages) EXPECT_EQ(a.level, expected) << "bias " << bias;
        // The pages cover the 10 x 10 square seen: (10 / page width)² of them, give or take a row and column.
        const double page_width = texel0 * std::ldexp(1.0, expected) * 128.0;
        const double side = 10.0 / page_width;
        EXPECT_GE(double(table.pages.size()), side * side);
        EXPECT_LE(double(table.pages.size()), (side + 2) * (side + 2));
        EXPECT_TRUE(setup.fallbacks.empty()) << describe(setup.fallbacks);
    }
}

TEST(Virtual, EverySeenPointReadsTheFinestResidentPageThatHoldsItInsideTheUnitCube) {
    const ShadowInputs in = seen_inputs(default_scene(), 2048);
    const ShadowSetup setup = run_virtual(in);
    ASSERT_TRUE(in.seen_receivers && !in.seen_receivers->points.empty());
    const PageTable& table = setup.selection.pages;
    for (const glm::dvec3& p : in.seen_receivers->points) {
        const int map = select_map(setup, p);
        ASSERT_GE(map, 0);
        EXPECT_TRUE(in_unit_cube(world_to_uvz(setup.maps[map], p), 1e-9));
        const PageAddress& read = table.pages[map];
        for (int finer = 0; finer < read.level; ++finer)
            if (const std::optional<PageAddress> a = page_holding(table, finer, p)) {
                EXPECT_LT(table.map_of(*a), 0);
            }
        // The page's tile is its slot: page_size texels of the texture.
        EXPECT_DOUBLE_EQ(tile_resolution(setup.maps[map], in.texture_resolution), table.page_size);
    }
}

TEST(Virtual, TheBudgetIsNeverExceededAndTheExcessIsNamed) {
    const ShadowInputs in = seen_inputs(default_scene(), 8192);
    const int marked = int(run_virtual(in).selection.pages.pages.size());
    ASSERT_GT(marked, 16);
    for (int budget : {1, 4, 16, marked - 1, marked, 4096}) {
        const ShadowSetup setup = run_virtual(in, {{"page_budget", std::to_string(budget)}});
        const PageTable& table = setup.selection.pages;
        EXPECT_LE(int(table.pages.size()), budget);
        EXPECT_EQ(table.counts.marked, marked);
        EXPECT_EQ(table.counts.budget, budget);
        EXPECT_EQ(has_note(setup.fallbacks, NoteKind::over_page_budget), budget < marked) << budget;
        EXPECT_EQ(table.counts.over_budget, std::max(0, marked - int(table.pages.size())));
        // Every seen point still reads a page, the excess fallen to coarser levels, unless even the
        // coarsest pages do not fit: the scene's centre is a corner of every level's grid, so the
        // coarsest level holds the view in up to four pages.
        std::size_t unread = 0;
        for (const glm::dvec3& p : in.seen_receivers->points) unread += select_map(setup, p) < 0;
        EXPECT_EQ(unread > 0, table.counts.dropped > 0) << budget;
        EXPECT_EQ(table.counts.dropped > 0, budget < 4) << budget;
        EXPECT_EQ(table.counts.dropped > 0, describe(setup.fallbacks).find("without a slot") != std::string::npos);
    }
    // The pool holds (resolution / page_size)² slots: a 512² texture four pages of 128².
    ShadowInputs small = in;
    small.texture_resolution = 512;
    EXPECT_EQ(run_virtual(small).selection.pages.counts.budget, 16);
}

// Within the budget, a pixel reads texels no wider than itself: m_perspective (Lloyd's factor)
// lies in (1/2, 1] up to the footprint's change across the image and a texel's diagonal.
TEST(Virtual, WithinTheBudgetPerspectiveAliasingIsAtMostOneAndAHalf) {
    const MeasureContext context = prepare_measurement(default_scene(), 640, 360);
    const Measurement m =
        measure(context, virtual_method(), resolve_settings("virtual", virtual_method().settings, {}), 2048, -1.0);
    ASSERT_TRUE(m.pages.has_value());
    EXPECT_EQ(m.pages->counts.over_budget, 0);
    EXPECT_GT(m.error.m_perspective.mean, 0.5);
    EXPECT_LE(m.error.m_perspective.p95, 1.5);
    EXPECT_LE(m.error.m_perspective.max, 2.0);
    // The same view at 1024², its 64 slots too few: the bias rises, and aliasing with it.
    const Measurement tight =
        measure(context, virtual_method(), resolve_settings("virtual", virtual_method().settings, {}), 1024, -1.0);
    EXPECT_TRUE(has_note(tight.fallbacks, NoteKind::over_page_budget));
    EXPECT_GT(tight.error.m_perspective.p95, m.error.m_perspective.p95);
}

TEST(Virtual, MeasureReportsItsPages) {
    const ShadowSetup setup = run_virtual(seen_inputs(default_scene(), 2048));
    const Json pages = pages_json(setup.selection.pages);
    for (const char* key : {"resident", "budget", "page_size", "levels", "over_budget"})
        EXPECT_TRUE(pages.contains(key)) << key;
    EXPECT_EQ(pages["resident"].get<std::size_t>(), setup.maps.size());
    EXPECT_EQ(pages["budget"].get<int>(), 256);
    EXPECT_EQ(pages["page_size"].get<int>(), 128);
    EXPECT_EQ(pages["levels"].get<int>(), 16);
}

// A page cache draws only the pages a frame newly needs; a sideways path keeps most of them, and
// pages that keep their texels flip no verdict, as stabilized cascades flip none.
TEST(Virtual, ACachedSidewaysPathDrawsFarFewerTexelsAndFlipsNoMoreThanStabilizedCascades) {
    const MeasureContext context = prepare_measurement(default_scene(), 320, 180);
    const std::vector<ShimmerSample> samples = shimmer_samples(context);
    const CameraPath path{CameraPath::Kind::translate, 8, 0.0};
    const Shimmer pages = measure_shimmer(context, samples, virtual_method(),
                                          resolve_settings("virtual", virtual_method().settings, {}), 2048, -1.0, path);
    const Method& cascades = method_or_throw("cascades");
    const Shimmer stabilized =
        measure_shimmer(context, samples, cascades,
                        resolve_settings("cascades", cascades.settings, {{"stabilize", "on"}}), 2048, -1.0, path);
    ASSERT_GT(pages.transitions(), 1000u);
    EXPECT_LT(pages.texels_cached_per_frame(), 0.1 * pages.texels_fresh_per_frame());
    EXPECT_LE(pages.flips(), stabilized.flips());
    std::size_t kept = 0;
    for (std::size_t i = 1; i < pages.frames.size(); ++i) kept += pages.frames[i].pages.kept;
    EXPECT_GT(kept, 0u);
    EXPECT_EQ(stabilized.texels_cached_per_frame(), stabilized.texels_fresh_per_frame());
}

TEST(Virtual, WithoutADepthImageOrASunItIsTheUniformMapNamed) {
    ShadowInputs in = gather_inputs(default_scene());
    EXPECT_TRUE(has_note(run_virtual(in).fallbacks, NoteKind::no_depth_image));
    in.light.type = LightType::point;
    in.light.position = {0, 10, 0};
    trace_depth_image(in, default_scene(), tessellate(default_scene()), 64, 36);
    EXPECT_TRUE(has_note(run_virtual(in).fallbacks, NoteKind::not_directional));
}

// Its texels are sized by the resolution bias, not the texture (the pool): the remedy for
// under-sampling and projection aliasing lowers the bias by log2 of the factor, rounded up.
TEST(Virtual, FinerTexelsLowerTheResolutionBiasNotRaiseTheResolution) {
    const Settings defaults = resolve_settings("virtual", virtual_method().settings, {});
    const RemedyInputs in{
        .method = virtual_method(), .settings = defaults, .resolution = 2048, .m_perspective_p95 = 1.2, .m_p95 = 3.5};
    const std::optional<Remedy> projection = info(PixelCause::projection).remedy(in);
    ASSERT_TRUE(projection.has_value());
    EXPECT_EQ(projection->resolution, 2048);
    EXPECT_EQ(projection->settings.number("resolution_bias"), -2.0);
    EXPECT_EQ(projection->change, "resolution_bias 0 → -2");
    const std::optional<Remedy> under = info(PixelCause::under_sampling).remedy(in);
    ASSERT_TRUE(under.has_value());
    EXPECT_EQ(under->settings.number("resolution_bias"), -1.0);
    const Settings finest = resolve_settings("virtual", virtual_method().settings, {{"resolution_bias", "-4"}});
    EXPECT_FALSE(virtual_finer_texels(finest, 4.0).has_value());
}

// The pages are drawn from the casters binned to them; every page clipping every caster (the same
// maps under another rule) draws the same texels.
TEST(Virtual, PagesDrawnFromTheirBinnedCastersEqualPagesDrawnFromEveryCaster) {
    const Scene scene = default_scene();
    const ShadowInputs in = seen_inputs(scene, 2048);
    const ShadowSetup setup = run_virtual(in);
    ASSERT_GT(setup.maps.size(), 20u);
    ShadowSetup unbinned = setup;
    unbinned.selection.rule = MapSelection::Rule::tile_bounds;
    const WorldTriangles triangles = tessellate(scene);
    const std::vector<bool> casters = caster_flags(scene);
    const DepthMap binned = rasterize_depth(triangles, casters, setup, 2048);
    const DepthMap every = rasterize_depth(triangles, casters, unbinned, 2048);
    EXPECT_TRUE(binned.codes == every.codes);
    EXPECT_LT(std::count(binned.codes.begin(), binned.codes.end(), binned.codes.back()), long(binned.codes.size()));
}

// A camera moved a little sideways keeps most of its pages (each the same level and square of its
// grid), and the maps marked kept are exactly those the turnover counts.
TEST(Virtual, AMovedCameraKeepsThePagesStillNeededAndSaysWhichTheyAre) {
    const Scene scene = default_scene();
    const ShadowInputs here = seen_inputs(scene, 2048);
    Scene moved = scene;
    moved.camera = camera_at(scene.camera, CameraPath{CameraPath::Kind::translate, 2, 0.0}, 1);
    const ShadowInputs there = seen_inputs(moved, 2048);
    const ShadowSetup before = run_virtual(here), now = run_virtual(there);
    const std::vector<bool> kept = kept_maps(&before, now);
    ASSERT_EQ(kept.size(), now.maps.size());
    const PageTurnover turnover = page_turnover(&before, now);
    EXPECT_EQ(std::size_t(std::count(kept.begin(), kept.end(), true)), turnover.kept);
    EXPECT_GT(turnover.kept, 9 * turnover.allocated);
    EXPECT_EQ(turnover.kept + turnover.freed, before.maps.size());
    const std::vector<bool> first_frame = kept_maps(nullptr, now);
    EXPECT_EQ(std::count(first_frame.begin(), first_frame.end(), true), 0);
}

// One level of 16 x 16 pages, every page resident in the slot where it lies in the level: the pool
// is then the level's own map texel for texel, and a filter's kernel reads across page edges
// (ShadowReader::tap_texel) as it reads across that one map's texels: the same visibility.
TEST(Virtual, FilterKernelsReadAcrossPageEdgesAsAcrossOneMap) {
    const Scene scene = load_scene(source_path("data/scenes/soft_shadows.json"));
    const ShadowInputs in = gather_inputs(scene);
    const Clipmap c = clipmap_around(in, {.levels = 1, .first_level_radius = 1.0, .virtual_resolution = 2048});
    ShadowSetup pages{.selection = {.rule = MapSelection::Rule::pages, .pages = c.table}};
    PageTable& table = pages.selection.pages;
    const int n = table.pages_per_side;
    ASSERT_EQ(n, 16);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const PageAddress a{.level = 0, .page = {x, y}};
            table.resident[table.index(a)] = int(pages.maps.size());
            table.pages.push_back(a);
            pages.maps.push_back(
                {.world_to_uvz = page_world_to_uvz(table, a), .viewport = glm::dvec4(x, y, x + 1, y + 1) / double(n)});
        }
    const ShadowSetup one{.maps = {ShadowMap{.world_to_uvz = table.levels[0].world_to_uvz}}};
    const WorldTriangles triangles = tessellate(scene);
    const std::vector<bool> casters = caster_flags(scene);
    const DepthMap paged_depth = rasterize_depth(triangles, casters, pages, 2048);
    const DepthMap one_depth = rasterize_depth(triangles, casters, one, 2048);
    ASSERT_TRUE(paged_depth.codes == one_depth.codes) << "the pool is not the level's map";
    const ReferenceImage seen = visible_points(scene, triangles, 320, 180);
    for (const auto& settings : std::vector<std::map<std::string, std::string>>{
             {{"filter", "pcf"}, {"pcf_kernel", "poisson"}, {"kernel_size", "4"}, {"filter_radius", "3"}},
             {{"filter", "pcf"}, {"pcf_kernel", "box"}, {"kernel_size", "5"}, {"filter_radius", "2"}},
             {{"filter", "pcss"}},
             {{"filter", "pcf"}, {"kernel_size", "3"}, {"bias_receiver_plane", "on"}}}) {
        const ShadowLookup lookup =
            lookup_from(resolve_settings("focused", method_or_throw("focused").settings, settings));
        const ShadowReader paged(pages, paged_depth, scene.light, lookup), whole(one, one_depth, scene.light, lookup);
        std::size_t compared = 0, shaded = 0;
        double worst = 0.0;
        for (std::size_t i = 0; i < seen.visible.size(); ++i) {
            if (!seen.visible[i] || !scene.objects[seen.object[i]].receives) continue;
            const Receiver r{.position = seen.position[i], .normal = seen.normal[i], .rotation = double(i % 7)};
            const double v = paged.visibility(r);
            worst = std::max(worst, std::abs(v - whole.visibility(r)));
            ++compared;
            shaded += v < 1.0;
        }
        ASSERT_GT(compared, 10000u);
        ASSERT_GT(shaded, 1000u) << "no shadow seen: nothing compared across page edges";
        EXPECT_LT(worst, 1e-9) << settings.at("filter");
    }
}
