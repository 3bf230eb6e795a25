// The flatland cross-section (core/flatland): the plane of the view and the light, the sections of
// the frustum and B, the texel boundaries traced in it, and the texel density along the view.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "flatland/flatland.hpp"
#include "flatland/texel_density.hpp"
#include "maps/map_lookup.hpp"
#include "registry/method.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

namespace shadowlab {
namespace {

constexpr int kResolution = 1024;

struct MethodRun {
    ShadowInputs inputs;
    ShadowSetup setup;
};

MethodRun run(const std::string& method, const Scene& scene) {
    const Method& m = method_or_throw(method);
    MethodRun r{gather_inputs(scene), {}};
    r.setup = m.compute_maps(r.inputs, resolve_settings(method, m.settings, {}), nullptr);
    return r;
}

Scene teaching() { return load_scene(testing::source_path("data/scenes/teaching.json")); }

TEST(Flatland, LispsmTexelLinesFanOutAlongTheView) {
    const MethodRun r = run("lispsm", teaching());
    ASSERT_TRUE(r.setup.fallbacks.empty()) << describe(r.setup.fallbacks);
    const std::optional<AxisLineDensity> lines = axis_line_density(flatland(r.inputs, r.setup, kResolution));
    ASSERT_TRUE(lines);
    ASSERT_GT(lines->far_lines, 0.0);
    // The warp spends its texels near the eye: boundaries crowd there and spread out far away.
    EXPECT_GT(lines->near_lines, 3.0 * lines->far_lines)
        << lines->near_lines << " near, " << lines->far_lines << " far";
}

TEST(Flatland, UniformTexelLinesAreEvenlySpacedAlongTheView) {
    const MethodRun r = run("uniform", teaching());
    const std::optional<AxisLineDensity> lines = axis_line_density(flatland(r.inputs, r.setup, kResolution));
    ASSERT_TRUE(lines);
    // Equal stretches of the view axis hold as many boundaries, but for the one a stretch's ends may cut off.
    const double stretch = lines->near.far - lines->near.near;
    const double near_count = lines->near_lines * stretch, far_count = lines->far_lines * stretch;
    ASSERT_GE(far_count, 3.0);
    EXPECT_LE(std::abs(near_count - far_count), 1.0 + 1e-9) << near_count << " near, " << far_count << " far";
}

TEST(Flatland, TexelLinesLieInThePlaneOnTheirTexelBoundaries) {
    for (const std::string method : {"uniform", "lispsm", "cascades"}) {
        const MethodRun r = run(method, teaching());
        const Flatland f = flatland(r.inputs, r.setup, kResolution);
        ASSERT_FALSE(f.texel_lines.empty()) << method;
        const Plane plane = f.plane.plane();
        const double scale = r.inputs.scene_bounds.diagonal();
        size_t points = 0;
        for (const TexelLine& line : f.texel_lines) {
            EXPECT_EQ(line.index % f.stride, 0) << method;
            for (const glm::dvec3& p : line.points) {
                ++points;
                ASSERT_LT(std::abs(plane.signed_distance(p)), 1e-9 * scale) << method;
                const double texels = tile_resolution(r.setup.maps[line.map], kResolution);
                ASSERT_NEAR(world_to_uvz(r.setup.maps[line.map], p)[line.axis] * texels, line.index, 1e-6) << method;
            }
        }
        EXPECT_GT(points, 2 * f.texel_lines.size()) << method;
    }
}

TEST(Flatland, StrideKeepsTheDensestLinesReadable) {
    const MethodRun r = run("lispsm", teaching());
    const Flatland coarse = flatland(r.inputs, r.setup, 1024), fine = flatland(r.inputs, r.setup, 4096);
    EXPECT_EQ(fine.texels, 4096);
    EXPECT_EQ(fine.stride, 4 * coarse.stride);  // the same lines: k grows with R
    EXPECT_EQ(view_axis_crossings(coarse, 0.0, 1e9), view_axis_crossings(fine, 0.0, 1e9));
}

// A plane through the eye holding the view axis cuts the camera's pyramid in the wedge of rays
// eye + z (V + τ A), |τ| <= tan φ, with A the plane's direction across V: a ray's image point
// (x, y) / z = τ (A · right, A · up) leaves the image where τ |A · right| = tan(half width) or
// τ |A · up| = tan(half height), whichever comes first. From near to far the wedge is a trapezoid.
TEST(Flatland, FrustumSectionIsTheAnalyticTrapezoid) {
    const Scene scene = teaching();
    const MethodRun r = run("focused", scene);
    const Flatland f = flatland(r.inputs, r.setup, kResolution);
    const Camera& c = scene.camera;
    const glm::dvec3 v = c.view_direction(), right = glm::normalize(glm::cross(v, c.up)), up = glm::cross(right, v),
                     a = f.plane.across;
    const double tan_half_height = std::tan(glm::radians(c.fov_y_deg) / 2), tan_half_width = c.aspect * tan_half_height;
    const double tan_phi =
        1.0 / std::max(std::abs(glm::dot(a, right)) / tan_half_width, std::abs(glm::dot(a, up)) / tan_half_height);
    ASSERT_EQ(f.frustum.size(), 4u);
    for (double z : {c.near, c.far})
        for (double side : {-1.0, 1.0}) {
            const glm::dvec3 expected = c.position + z * (v + side * tan_phi * a);
            double nearest = INFINITY;
            for (const glm::dvec3& corner : f.frustum) nearest = std::min(nearest, glm::length(corner - expected));
            EXPECT_LT(nearest, 1e-9 * c.far) << "z " << z << " side " << side;
        }
}

TEST(Flatland, BodySectionLiesInBothThePlaneAndTheFrustumsShadowReach) {
    const MethodRun r = run("lispsm", teaching());
    const Flatland f = flatland(r.inputs, r.setup, kResolution);
    ASSERT_GE(f.body.size(), 3u);
    const double scale = r.inputs.scene_bounds.diagonal();
    for (const glm::dvec3& p : f.body) {
        EXPECT_LT(std::abs(f.plane.plane().signed_distance(p)), 1e-9 * scale);
        EXPECT_TRUE(r.inputs.scene_bounds.contains(p, 1e-9 * scale));
    }
    // LiSPSM's map holds B: its volume's section contains B's.
    ASSERT_EQ(f.map_volumes.size(), 1u);
    const Frustum volume = map_volume(r.setup.maps[0]);
    for (const glm::dvec3& p : f.body) EXPECT_TRUE(volume.contains(p, 1e-6 * scale));
}

TEST(TexelDensity, UniformIsConstantAndTheIdealFallsAsOneOverDepth) {
    const MethodRun r = run("uniform", teaching());
    const std::vector<DensitySample> samples = texel_density_over_view(r.inputs, r.setup, kResolution, 720);
    ASSERT_EQ(samples.size(), size_t(kDensityDepths));  // the map holds the whole view axis through the scene
    for (const DensitySample& s : samples) {
        EXPECT_NEAR(s.texels / samples.front().texels, 1.0, 1e-9);  // orthographic: the same texels everywhere
        // m_p = 1: one texel per pixel footprint 2 z tan(θ/2) / H
        EXPECT_NEAR(s.ideal * s.depth, 720 / (2 * std::tan(glm::radians(r.inputs.camera.fov_y_deg) / 2)), 1e-9);
    }
}

TEST(TexelDensity, LispsmFallsAlongTheViewBetweenUniformAndTheIdeal) {
    const MethodRun r = run("lispsm", teaching());
    const std::vector<DensitySample> samples = texel_density_over_view(r.inputs, r.setup, kResolution, 720);
    ASSERT_EQ(samples.size(), size_t(kDensityDepths));
    for (size_t i = 1; i < samples.size(); ++i) EXPECT_LT(samples[i].texels, samples[i - 1].texels);
    // Falling, but slower than 1/z: the warp is a compromise (Lloyd's η = 0 halves the log's exponent).
    const double fall = samples.front().texels / samples.back().texels;
    const double ideal_fall = samples.front().ideal / samples.back().ideal;
    EXPECT_GT(fall, 2.0);
    EXPECT_LT(fall, ideal_fall);
}

// The boundaries the flatland traces across the view axis are the density's integral: two ways to
// the same count (per axis: a boundary of u or of v crossed is one line).
TEST(TexelDensity, LinesCrossingTheViewAxisAreTheDensitysIntegral) {
    for (const std::string method : {"uniform", "lispsm"}) {
        const MethodRun r = run(method, teaching());
        const Flatland f = flatland(r.inputs, r.setup, kResolution);
        const std::optional<DepthSpan> span = view_axis_span(r.inputs);
        ASSERT_TRUE(span);
        std::vector<double> depths;
        constexpr int kSteps = 4000;
        for (int i = 0; i <= kSteps; ++i) depths.push_back(span->near + (span->far - span->near) * i / kSteps);
        const std::vector<DensitySample> samples =
            texel_density_along_view(r.setup, r.inputs.camera, kResolution, 720, depths);
        ASSERT_EQ(samples.size(), depths.size()) << method;
        double integral = 0.0;  // trapezoids
        for (size_t i = 1; i < samples.size(); ++i)
            integral +=
                0.5 * (samples[i].depth - samples[i - 1].depth) *
                (samples[i].per_axis.x + samples[i].per_axis.y + samples[i - 1].per_axis.x + samples[i - 1].per_axis.y);
        const int counted = view_axis_crossings(f, span->near, span->far);
        EXPECT_GT(counted, 5) << method;
        EXPECT_NEAR(counted, integral / f.stride, 2.0) << method;
    }
}

TEST(Flatland, LightAlongTheViewFallsBackToThePlaneOfTheCamerasUp) {
    Scene scene = teaching();
    scene.light.direction = scene.camera.view_direction();
    const FlatlandChoice choice = flatland_plane(scene.camera, scene.light);
    ASSERT_TRUE(choice.fallback);
    EXPECT_EQ(choice.fallback->kind, NoteKind::light_along_view);
    EXPECT_NEAR(glm::dot(choice.plane.along, choice.plane.across), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(choice.plane.normal(), scene.camera.up), 0.0, 1e-12);  // the plane holds the up
    EXPECT_GT(glm::dot(choice.plane.across, scene.camera.up), 0.0);
    // Off the view by a little more than the threshold: the light's own plane, no note.
    scene.light.direction = glm::normalize(scene.camera.view_direction() + 0.01 * glm::dvec3(1, 0, 0));
    const FlatlandChoice own = flatland_plane(scene.camera, scene.light);
    EXPECT_FALSE(own.fallback);
    EXPECT_NEAR(glm::dot(own.plane.normal(), scene.light.direction), 0.0, 1e-12);
}

}  // namespace
}  // namespace shadowlab
