// The storage lower bound and each method's storage efficiency (metrics/storage_bound.hpp, after
// Lloyd et al. 2006 and 2008): the bound against its closed forms for a plane seen from above under
// a tilted sun and under a spot, and against a sum computed here for a perspective view of a plane;
// the focused and uniform maps' efficiencies against theirs; the texels a method needs not
// following its resolution (m_perspective halves as the resolution doubles); every registered
// method's efficiency at most 1.
#include <gtest/gtest.h>

#include <cmath>

#include "metrics/max_density_grid.hpp"
#include "metrics/measurement.hpp"
#include "metrics/storage_bound.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using shadowlab::testing::camera_20_units_above_the_origin;
using shadowlab::testing::source_path;

namespace {

// A measure context whose measures report their storage, as `measure`, `bench` and `compare` make it.
MeasureContext context_with_bounds(const Scene& scene, int width, int height) {
    MeasureContext context = prepare_measurement(scene, width, height);
    add_storage_bounds(context);
    return context;
}

constexpr int kPixels = 128;  // the test views' image side
// The grid draws each pixel's footprint at the level of its own size (metrics/max_density_grid.hpp):
// where neighbouring footprints fall to different levels it misses up to half a coarse cell of the
// coarser one, so a bound whose density varies across the image comes out up to about 2 % low.
constexpr double kGridShare = 0.03;
constexpr double kViewHalfSide = 10;  // the orthographic view's half side: 20 x 20 units of ground

// A 40 x 40 ground, seen straight down by an orthographic camera over its middle 20 x 20, lit by a
// sun `tilt_deg` off the vertical in the x-y plane.
Scene ground_seen_from_above(double tilt_deg) {
    Scene scene;
    scene.objects.push_back({.name = "ground", .shape = Shape::plane, .size = {40.0, 1.0, 40.0}});
    const double tilt = glm::radians(tilt_deg);
    scene.light.direction = {std::sin(tilt), -std::cos(tilt), 0.0};
    scene.camera = {.position = {0.0, 20.0, 0.0},
                    .target = {0.0, 0.0, 0.0},
                    .up = {0.0, 0.0, -1.0},
                    .aspect = 1.0,
                    .near = 1.0,
                    .far = 40.0,
                    .projection = CameraProjection::orthographic,
                    .half_height = kViewHalfSide};
    return scene;
}

Measurement measured(const MeasureContext& context, const std::string& name, int resolution) {
    const Method& method = method_or_throw(name);
    return measure(context, method, resolve_settings(name, method.settings, {}), resolution, -1.0);
}

// A parallelogram grid tiling the rectangle [x0, x0 + columns·step) × [y0, y0 + rows·step), each
// cell asking `density`.
void tile(MaxDensityGrid& grid, double x0, double y0, int columns, int rows, double step, double density) {
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i)
            grid.add(0, {x0 + (i + 0.5) * step, y0 + (j + 0.5) * step}, {step, 0.0}, {0.0, step}, {density, density});
}

}  // namespace

// Two surfaces one behind the other: a dense one over [0, 1]² (density 4, cells 0.1 wide) and a
// sparse one over [0.5, 1.5] × [0, 1] (density 1, cells 0.2 wide, another level of the grid).
// Where both lie the dense one counts: 4 · 1 + 1 · 0.5. Alone, each integrates to its density
// times its area.
TEST(Storage, GridIntegratesTheLargestDensityWhereSurfacesOverlap) {
    MaxDensityGrid dense, sparse, both;
    tile(dense, 0.0, 0.0, 10, 10, 0.1, 4.0);
    tile(sparse, 0.5, 0.0, 5, 5, 0.2, 1.0);
    tile(both, 0.0, 0.0, 10, 10, 0.1, 4.0);
    tile(both, 0.5, 0.0, 5, 5, 0.2, 1.0);
    EXPECT_NEAR(dense.integral().x, 4.0, 1e-9);
    EXPECT_NEAR(sparse.integral().x, 1.0, 1e-9);
    EXPECT_NEAR(both.integral().x, 4.5, 1e-9);
    EXPECT_GT(both.cells(), dense.cells());
}

// Sheared, turned parallelograms tiling a region mark its area to within their outline's half
// cells: 400 footprints of a lattice with edges (0.3, 0.1) and (-0.05, 0.2), density 2; the
// second density only over the first ten columns.
TEST(Storage, GridDrawsATilingOfShearedFootprintsToItsArea) {
    MaxDensityGrid grid;
    const glm::dvec2 a(0.3, 0.1), b(-0.05, 0.2);
    for (int j = 0; j < 20; ++j)
        for (int i = 0; i < 20; ++i) grid.add(0, (i + 0.5) * a + (j + 0.5) * b, a, b, {2.0, i < 10 ? 2.0 : 0.0});
    const double area = 400.0 * std::abs(glm::determinant(glm::dmat2(a, b)));
    EXPECT_NEAR(grid.integral().x, 2.0 * area, 0.02 * 2.0 * area);
    EXPECT_NEAR(grid.integral().y, area, 0.02 * area) << "the second density: half of the footprints";
}

// Under a sun tilted θ off the vertical, seen straight down by an orthographic camera: every
// pixel's view ray is vertical, its halfway plane is tilted θ/2, and its footprint slid onto that
// plane and along the light onto the light's image plane keeps its size, (20/128)² (the halfway
// plane's isometry): that is the largest texel area allowed anywhere. The ground's 20 x 20 units
// cover 20 cos θ x 20 of the light's image plane, so the bound is 128² cos θ: one texel a pixel
// times cos φ_light / cos φ_eye. The focused map fits the same 20 cos θ x 20 into its square, its
// texels 20 / N along z set its max m, 128 / N: it needs 128² texels, efficiency cos θ. The
// uniform map fits the whole 40 x 40 ground: twice the texel width, four times the texels,
// efficiency cos θ / 4.
TEST(Storage, BoundOfAnOrthographicViewOfAPlaneIsCosThetaTexelsAPixel) {
    for (const double tilt_deg : {0.0, 30.0, 60.0}) {
        SCOPED_TRACE(tilt_deg);
        const MeasureContext context = context_with_bounds(ground_seen_from_above(tilt_deg), kPixels, kPixels);
        ASSERT_EQ(context.reference.width, kPixels);
        const double cos_theta = std::cos(glm::radians(tilt_deg));
        const double closed_form = kPixels * kPixels * cos_theta;
        EXPECT_NEAR(context.storage_bounds->every_receiver, closed_form, kGridShare * closed_form);
        const Measurement focused = measured(context, "focused", 512);
        ASSERT_TRUE(focused.storage);
        EXPECT_NEAR(focused.storage->needed, kPixels * kPixels, 0.03 * kPixels * kPixels);
        EXPECT_NEAR(focused.storage->efficiency, cos_theta, 0.03 * cos_theta);
        const Measurement uniform = measured(context, "uniform", 512);
        EXPECT_NEAR(uniform.storage->efficiency, cos_theta / 4, 0.03 * cos_theta / 4);
    }
}

// A pinhole camera 20 units above a plane, looking straight down (60°, 128 x 128 pixels), a sun
// 40° off the vertical. A pixel whose ray leaves the axis at α sees (20 δ)² of ground (δ: its side
// on the image plane at distance 1), which covers (20 δ)² cos θ of the light's image plane; its
// footprint across the ray, δ² cos³α · (20 / cos α)², is the texel area allowed there. The bound
// is the sum over the pixels of cos θ / cos α = cos θ √(1 + x² + y²), (x, y) the pixel centre on
// the image plane at distance 1: summed here from the camera's field of view alone.
TEST(Storage, BoundOfAPerspectiveViewOfAPlaneIsTheSumOfCosThetaOverCosAlpha) {
    Scene scene;
    scene.objects.push_back({.name = "ground", .shape = Shape::plane, .size = {100.0, 1.0, 100.0}});
    const double tilt = glm::radians(40.0);
    scene.light.direction = {0.0, -std::cos(tilt), std::sin(tilt)};
    scene.camera = camera_20_units_above_the_origin();
    const MeasureContext context = context_with_bounds(scene, kPixels, kPixels);
    ASSERT_EQ(context.reference.width, kPixels);
    const double half = std::tan(glm::radians(scene.camera.fov_y_deg / 2));
    double sum = 0.0;
    for (int j = 0; j < kPixels; ++j)
        for (int i = 0; i < kPixels; ++i) {
            const double x = ((i + 0.5) / kPixels * 2 - 1) * half, y = ((j + 0.5) / kPixels * 2 - 1) * half;
            sum += std::cos(tilt) * std::sqrt(1 + x * x + y * y);
        }
    EXPECT_NEAR(context.storage_bounds->every_receiver, sum, kGridShare * sum);
    EXPECT_GT(sum, 1.1 * kPixels * kPixels * std::cos(tilt)) << "the corners count more than the centre";
    const Measurement focused = measured(context, "focused", 512);
    EXPECT_LE(focused.storage->efficiency, 1.0);
    EXPECT_GT(focused.storage->efficiency, 0.3);
}

// A spot light 6 units above the ground, seen straight down by the orthographic camera over 20 x 20
// units, so that the light's rays leave it up to 67° off straight down, through the cube's bottom
// face and its four sides. Per pixel the footprint across the view ray is the pixel's square and
// the bound counts cos φ_light / cos φ_eye = 6 / |p − light|: summed here over the pixel centres.
TEST(Storage, BoundUnderASpotLightCountsItsDirectionsOnEveryCubeFace) {
    Scene scene = ground_seen_from_above(0.0);
    scene.light = {
        .type = LightType::spot, .direction = {0.0, -1.0, 0.0}, .position = {0.0, 6.0, 0.0}, .cone_deg = 150.0};
    const MeasureContext context = context_with_bounds(scene, kPixels, kPixels);
    ASSERT_EQ(context.reference.width, kPixels);
    double sum = 0.0;
    const double pixel = 2 * kViewHalfSide / kPixels;
    for (int j = 0; j < kPixels; ++j)
        for (int i = 0; i < kPixels; ++i) {
            const glm::dvec3 p(-kViewHalfSide + (i + 0.5) * pixel, 0.0, -kViewHalfSide + (j + 0.5) * pixel);
            sum += 6.0 / glm::length(p - scene.light.position);
        }
    EXPECT_NEAR(context.storage_bounds->every_receiver, sum, kGridShare * sum);
    EXPECT_LT(sum, 0.7 * kPixels * kPixels) << "the far pixels are seen obliquely by the light";
}

// needed = texels × (max m_perspective)² does not follow the resolution: m_perspective scales as
// 1 / N, so doubling the resolution halves it and quadruples the texels. Checked for every
// registered map method whose texels follow the texture's resolution (a method whose texel size is
// a setting, Method::finer_texels, keeps its m as the texture grows).
TEST(Storage, PerspectiveMHalvesAsTheResolutionDoubles) {
    const MeasureContext context = context_with_bounds(load_scene(source_path("data/scenes/default.json")), 160, 90);
    int checked = 0;
    for (const Method& method : all_methods()) {
        if (!method.makes_maps() || method.finer_texels) continue;
        SCOPED_TRACE(method.name);
        const Measurement coarse = measured(context, method.name, 512), fine = measured(context, method.name, 1024);
        ASSERT_GT(coarse.error.m_perspective.max, 0.0);
        EXPECT_NEAR(coarse.error.m_perspective.max / fine.error.m_perspective.max, 2.0, 0.1);
        EXPECT_NEAR(fine.storage->needed / coarse.storage->needed, 1.0, 0.1);
        ++checked;
    }
    EXPECT_GE(checked, 8);
}

// lower_bound <= needed for any map (the header's derivation), up to the one-pixel finite
// differences both are measured with and the grid's half-cell outlines: 2 %. Every registered map
// method on scenes of a sun, a spot and a point light, each against the bound over the receivers
// it promises to cover (the warps': those in shadow); a technique has no texels and no storage.
TEST(Storage, EveryMethodsEfficiencyIsAtMostOne) {
    constexpr double kTolerance = 1.02;
    int checked = 0;
    for (const std::string scene : {"default", "spot", "point", "box_on_plane"}) {
        const MeasureContext context =
            context_with_bounds(load_scene(source_path("data/scenes/" + scene + ".json")), 160, 90);
        const StorageBounds& bounds = *context.storage_bounds;
        ASSERT_GT(bounds.shadowed_receivers, 0.0) << scene;
        ASSERT_LT(bounds.shadowed_receivers, bounds.every_receiver) << scene;
        for (const Method& method : all_methods()) {
            SCOPED_TRACE(scene + " " + method.name);
            const Measurement m = measured(context, method.name, 1024);
            if (!method.makes_maps()) {
                EXPECT_FALSE(m.storage);
                continue;
            }
            ASSERT_TRUE(m.storage);
            EXPECT_GT(m.storage->efficiency, 0.0);
            EXPECT_LE(m.storage->efficiency, kTolerance)
                << "needed " << m.storage->needed << ", lower bound " << m.storage->lower_bound;
            ++checked;
        }
    }
    EXPECT_GE(checked, 4 * 10);
}
