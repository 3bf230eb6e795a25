// The stability sweep: 10,000 random light and camera configurations over every method, with the
// hard cases: light almost parallel to the view (γ down to 1e-6 rad) from behind and from in
// front, light overhead, casters behind the viewer (at the town's edge and 1e4 units back),
// far/near up to 1e7 and scene scales from 1e-3 to 1e6. Every method must give finite maps and
// only named fallbacks, keep visible receivers in the unit cube (orthographic fits) or the visible
// points a caster can shadow (every method).
#include <gtest/gtest.h>

#include "geometry/intersection_body.hpp"
#include "registry/method.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr double kTownSize = 500.0;
const std::array<double, 6> kScales{1e-3, 1e-1, 1.0, 1e2, 1e4, 1e6};

struct Configuration {
    Camera camera;
    Light light;
    size_t scale_index;
    bool far_caster;  // a caster 1e4 units behind the viewer
};

glm::dvec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<double> n;
    glm::dvec3 v;
    do v = {n(rng), n(rng), n(rng)};
    while (glm::length(v) < 1e-6);
    return glm::normalize(v);
}

// A direction at `angle` radians from `axis`.
glm::dvec3 tilted(const glm::dvec3& axis, double angle, std::mt19937& rng) {
    const glm::dvec3 side = glm::normalize(glm::cross(axis, random_unit(rng)));
    return std::cos(angle) * axis + std::sin(angle) * side;
}

Configuration random_configuration(int i, std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Configuration c{{}, {}, size_t(i) % kScales.size(), false};
    const double s = kScales[c.scale_index];
    c.camera.position =
        s * glm::dvec3((u(rng) - 0.5) * kTownSize, 0.5 + 30 * u(rng) * u(rng), (u(rng) - 0.5) * kTownSize);
    glm::dvec3 view = random_unit(rng);
    view.y = -std::abs(view.y) * 0.5;  // mostly toward the ground and horizon
    c.camera.target = c.camera.position + s * glm::normalize(view);
    c.camera.near = s * std::pow(10.0, -2.0 + 2.0 * u(rng));
    c.camera.far = c.camera.near * std::pow(10.0, 1.0 + 6.0 * u(rng));  // far/near from 10 to 1e7
    c.camera.fov_y_deg = 20 + 100 * u(rng);
    const glm::dvec3 v = c.camera.view_direction();
    const double gamma = std::pow(10.0, -6.0 + 5.0 * u(rng));  // 1e-6 to 0.1 rad
    switch ((i / kScales.size()) % 6) {
        case 0: c.light.direction = tilted(v, gamma, rng); break;   // from behind the viewer
        case 1: c.light.direction = tilted(-v, gamma, rng); break;  // toward the viewer
        case 2: c.light.direction = {0, -1, 0}; break;              // overhead
        case 3:  // casters behind the viewer: light from behind, camera at the town's edge
        case 4:  // and a caster 1e4 units behind it
            c.camera.position = s * glm::dvec3(0, 2, 0.52 * kTownSize);
            c.camera.target = s * glm::dvec3(0, 1.5, 0.5 * kTownSize);
            c.light.direction = glm::normalize(glm::dvec3(0.1 * (u(rng) - 0.5), -0.3 * u(rng) - 0.05, -1));
            c.far_caster = (i / kScales.size()) % 6 == 4;
            break;
        default: c.light.direction = random_unit(rng); break;
    }
    return c;
}

// The town at each scale, with and without a tall caster 1e4 units behind the edge camera.
std::vector<ObjectBox> town_boxes(double scale, bool far_caster) {
    std::vector<ObjectBox> boxes = object_boxes(random_town(150, kTownSize, 11));
    if (far_caster)
        boxes.push_back({{{-50, 0, 0.52 * kTownSize + 1e4}, {50, 400, 0.52 * kTownSize + 1e4 + 100}}, true, false});
    for (ObjectBox& b : boxes) b.box = {b.box.min * scale, b.box.max * scale};
    return boxes;
}

// How many points the sweep has checked lie in the unit cube: a sweep that checked none proved nothing.
struct PointsChecked {
    int receivers = 0, shadowable = 0;
};

void expect_sound_setup(const Method& method, const ShadowInputs& in, const ShadowSetup& setup, int i,
                        bool check_shadowable, PointsChecked& checked) {
    ASSERT_FALSE(setup.maps.empty());
    for (const ShadowMap& map : setup.maps) {
        ASSERT_TRUE(finite(map.world_to_uvz)) << method.name << " configuration " << i;
        ASSERT_TRUE(std::isfinite(map.z_bias_scale)) << method.name << " configuration " << i;
    }
    ASSERT_TRUE(are_fallbacks(setup.fallbacks)) << describe(setup.fallbacks);
    const double tol = 1e-7 * in.scene_bounds.diagonal();
    auto expect_covered = [&](const glm::dvec3& p, double tolerance) {
        const std::optional<glm::dvec3> uvz = setup_uvz(setup, p);
        ASSERT_TRUE(uvz && in_unit_cube(*uvz, tolerance))
            << method.name << " configuration " << i << ": (" << (uvz ? uvz->x : NAN) << ", " << (uvz ? uvz->y : NAN)
            << ", " << (uvz ? uvz->z : NAN) << ")";
    };
    if (method.covers == Coverage::visible_receivers)
        for (const glm::dvec3& p : in.receiver_points())
            if (in.frustum.contains(p, -tol)) {
                expect_covered(p, 1e-6);
                ++checked.receivers;
            }
    if (check_shadowable)
        for (const glm::dvec3& p : shadowable_visible_points(in)) {
            expect_covered(p, 1e-5);
            ++checked.shadowable;
        }
}

}  // namespace

TEST(StabilitySweep, TenThousandConfigurationsGiveFiniteMapsAndNamedFallbacks) {
    std::array<std::array<std::vector<ObjectBox>, 2>, kScales.size()> boxes;
    for (size_t k = 0; k < kScales.size(); ++k)
        boxes[k] = {town_boxes(kScales[k], false), town_boxes(kScales[k], true)};
    std::mt19937 rng(2026);
    std::map<std::string, int> fallbacks;
    PointsChecked checked;
    for (int i = 0; i < 10000; ++i) {
        const Configuration c = random_configuration(i, rng);
        const ShadowInputs in = gather_inputs(c.camera, c.light, boxes[c.scale_index][c.far_caster]);
        for (const Method* method : map_methods()) {
            const ShadowSetup setup =
                method->compute_maps(in, resolve_settings(method->name, method->settings, {}), nullptr);
            expect_sound_setup(*method, in, setup, i, i % 10 == 0, checked);
            if (::testing::Test::HasFatalFailure()) return;
            if (!setup.fallbacks.empty()) ++fallbacks[method->name];
        }
    }
    for (const auto& [name, count] : fallbacks) RecordProperty("fallbacks_" + name, count);
    // Most configurations see some of the town: millions of points were checked (16.6 million
    // receiver points and 4.9 million shadowable ones on 2026-12-02).
    EXPECT_GT(checked.receivers, 1000000);
    EXPECT_GT(checked.shadowable, 100000);
    RecordProperty("receivers_checked", checked.receivers);
    RecordProperty("shadowable_checked", checked.shadowable);
}

TEST(StabilitySweep, FloatClipperAgreesWithExactKernelOnRandomConfigurations) {
    std::mt19937 rng(99);
    int compared = 0;
    for (int i = 0; i < 300; ++i) {
        const Configuration c = random_configuration(i, rng);
        const ShadowInputs in = gather_inputs(c.camera, c.light, town_boxes(kScales[c.scale_index], c.far_caster));
        const BodyInput input{in.frustum, in.scene_bounds, in.light.homogeneous()};
        const IntersectionBody exact = intersection_body(input, BodyKernel::epeck);
        const IntersectionBody fast = intersection_body(input, BodyKernel::float_clipper);
        const double volume = exact.body.volume();
        const glm::dvec3 e = in.scene_bounds.extent();
        if (volume < 1e-9 * e.x * e.y * e.z) {  // (near-)empty: the float path must not invent volume
            EXPECT_LE(fast.body.volume(), 1e-6 * e.x * e.y * e.z) << "configuration " << i;
            continue;
        }
        ++compared;
        EXPECT_NEAR(fast.body.volume(), volume, 1e-4 * volume) << "configuration " << i;
        EXPECT_TRUE(is_closed(fast.body)) << "configuration " << i;
    }
    EXPECT_GT(compared, 200);
}
