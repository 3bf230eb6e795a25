// Invariants every method must keep on every shipped scene.
#include <gtest/gtest.h>

#include "geometry/intersection_body.hpp"
#include "reference/visible_depths.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

ShadowSetup run(const Method& method, const ShadowInputs& inputs, std::map<std::string, std::string> set = {},
                Trace* trace = nullptr) {
    return method.compute_maps(inputs, resolve_settings(method.name, method.settings, set), trace);
}

// Receiver corners inside the view frustum must land in the unit cube.
void expect_receivers_in_unit_cube(const ShadowInputs& in, const ShadowSetup& setup, const std::string& what) {
    const double tol = 1e-7 * in.scene_bounds.diagonal();
    int checked = 0;
    for (const glm::dvec3& p : in.receiver_points()) {
        if (!in.frustum.contains(p, -tol)) continue;
        ++checked;
        const std::optional<glm::dvec3> uvz = setup_uvz(setup, p);
        ASSERT_TRUE(uvz && in_unit_cube(*uvz, 1e-6))
            << what << ": receiver point maps to (" << (uvz ? uvz->x : NAN) << ", " << (uvz ? uvz->y : NAN) << ", "
            << (uvz ? uvz->z : NAN) << ")";
    }
    (void)checked;
}

}  // namespace

class MethodOnScene : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(MethodOnScene, VisibleReceiversMapIntoTheUnitCube) {
    const auto& [method_name, file] = GetParam();
    const Scene scene = load_scene(file);
    const ShadowInputs in = gather_inputs(scene);
    const Method& method = *find_method(method_name);
    const ShadowSetup setup = run(method, in);
    ASSERT_FALSE(setup.maps.empty());
    for (const ShadowMap& map : setup.maps) ASSERT_TRUE(finite(map.world_to_uvz));
    EXPECT_TRUE(are_fallbacks(setup.fallbacks)) << describe(setup.fallbacks);
    // Orthographic fits cover every visible receiver; warps cover what a caster can shadow.
    if (in.light.is_directional() && method.covers == Coverage::visible_receivers)
        expect_receivers_in_unit_cube(in, setup, method_name + " on " + file);
}

TEST_P(MethodOnScene, ShadowableVisiblePointsMapIntoTheUnitCube) {
    const auto& [method_name, file] = GetParam();
    const ShadowInputs in = gather_inputs(load_scene(file));
    if (!in.light.is_directional()) GTEST_SKIP() << "perspective light maps are checked by the depth test";
    const ShadowSetup setup = run(*find_method(method_name), in);
    const std::vector<glm::dvec3> points = shadowable_visible_points(in);
    ASSERT_FALSE(points.empty()) << "no visible point of " << file << " can be shadowed: the test would check nothing";
    for (const glm::dvec3& p : points) {
        const std::optional<glm::dvec3> uvz = setup_uvz(setup, p);
        ASSERT_TRUE(uvz && in_unit_cube(*uvz, 1e-6))
            << method_name << " on " << file << ": (" << (uvz ? uvz->x : NAN) << ", " << (uvz ? uvz->y : NAN) << ", "
            << (uvz ? uvz->z : NAN) << ")";
    }
}

TEST_P(MethodOnScene, DepthGrowsAlongEachLightRay) {
    const auto& [method_name, file] = GetParam();
    const Scene scene = load_scene(file);
    const ShadowInputs in = gather_inputs(scene);
    const ShadowSetup setup = run(*find_method(method_name), in);
    const double step = 1e-3 * in.scene_bounds.diagonal();
    for (const glm::dvec3& p : in.receiver_points()) {
        if (!in.frustum.contains(p)) continue;  // what a map must order is what the camera sees
        const glm::dvec3 ray = in.light.is_directional() ? in.light.direction : glm::normalize(p - in.light.position);
        const std::optional<MapPoint> at = map_point(setup, p);
        if (!at || !in_unit_cube(at->uvz(), 0.0)) continue;  // behind a point light, outside a spot's cone: not mapped
        const ShadowMap& map = setup.maps[at->map];          // the same map along the ray: its depths are ordered
        const glm::dvec3 a = world_to_uvz(map, p), b = world_to_uvz(map, p + step * ray);
        ASSERT_GT(b.z, a.z) << method_name << " on " << file;
        EXPECT_NEAR(a.x, b.x, 1e-9 + 1e-9 * std::abs(a.x));
        EXPECT_NEAR(a.y, b.y, 1e-9 + 1e-9 * std::abs(a.y));
    }
}

TEST_P(MethodOnScene, TraceIsRecordedOnlyWhenAskedAndMatchesTheUntracedResult) {
    const auto& [method_name, file] = GetParam();
    const ShadowInputs in = gather_inputs(load_scene(file));
    Trace trace;
    const ShadowSetup traced = run(*find_method(method_name), in, {}, &trace);
    const ShadowSetup plain = run(*find_method(method_name), in);
    EXPECT_GE(trace.steps().size(), 3u);
    ASSERT_TRUE(trace.find("output") || trace.find("output-0")) << "one output step, or one per map";
    ASSERT_EQ(traced.maps.size(), plain.maps.size());
    for (size_t i = 0; i < plain.maps.size(); ++i) EXPECT_EQ(traced.maps[i].world_to_uvz, plain.maps[i].world_to_uvz);
}

// The frames a viewer draws the scene in: the unit frame is the map itself, and in the light
// frame of a directional light a light ray keeps its x, y and moves along +z.
TEST_P(MethodOnScene, TraceFramesPutTheSceneInTheMethodsSpaces) {
    const auto& [method_name, file] = GetParam();
    const ShadowInputs in = gather_inputs(load_scene(file));
    Trace trace;
    const ShadowSetup setup = run(*find_method(method_name), in, {}, &trace);
    ASSERT_TRUE(trace.frame(Space::unit).has_value());
    EXPECT_EQ(*trace.frame(Space::unit), setup.maps[0].world_to_uvz);
    ASSERT_TRUE(trace.frame(Space::light).has_value()) << method_name << " on " << file;
    const glm::dmat4& to_light = *trace.frame(Space::light);
    // A light frame that is projective (PSM's light lives in post-perspective space) bends the rays.
    const bool affine = to_light[0][3] == 0.0 && to_light[1][3] == 0.0 && to_light[2][3] == 0.0;
    if (!in.light.is_directional() || !affine) return;
    const double step = 1e-2 * in.scene_bounds.diagonal();
    for (const glm::dvec3& p : in.receiver_points()) {
        const glm::dvec4 a = to_light * glm::dvec4(p, 1.0),
                         b = to_light * glm::dvec4(p + step * in.light.direction, 1.0);
        EXPECT_NEAR(a.x / a.w, b.x / b.w, 1e-9 * step);
        EXPECT_NEAR(a.y / a.w, b.y / b.w, 1e-9 * step);
        EXPECT_GT(b.z / b.w, a.z / a.w);
    }
}

static std::vector<std::tuple<std::string, std::string>> all_pairs() {
    std::vector<std::tuple<std::string, std::string>> pairs;
    for (const Method* m : map_methods())
        for (const std::string& f : shipped_scenes()) pairs.emplace_back(m->name, f);
    return pairs;
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, MethodOnScene, ::testing::ValuesIn(all_pairs()), [](const auto& info) {
    std::string name = std::get<0>(info.param) + "_" + std::filesystem::path(std::get<1>(info.param)).stem().string();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
});

// A method that covers only what the camera's depth image shows (virtual: its pages) covers every
// receiver point of that image, on every shipped scene under a sun (the others fall back, checked
// by MethodOnScene).
TEST(SeenPointsCoverage, EverySeenPointMapsIntoTheUnitCubeOfItsMap) {
    int checked = 0;
    for (const Method* method : map_methods()) {
        if (method->covers != Coverage::seen_points) continue;
        for (const std::string& file : shipped_scenes()) {
            const Scene scene = load_scene(file);
            ShadowInputs in = gather_inputs(scene);
            trace_depth_image(in, scene, tessellate(scene), 160, 90);
            const ShadowSetup setup = run(*method, in);
            EXPECT_TRUE(are_fallbacks(setup.fallbacks)) << describe(setup.fallbacks);
            if (!in.light.is_directional()) continue;
            ASSERT_FALSE(in.seen_receivers->points.empty()) << file << " shows no receiver";
            for (const glm::dvec3& p : in.seen_receivers->points) {
                const std::optional<glm::dvec3> uvz = setup_uvz(setup, p);
                ASSERT_TRUE(uvz && in_unit_cube(*uvz, 1e-9)) << method->name << " on " << file;
            }
            ++checked;
        }
    }
    EXPECT_GT(checked, 5) << "no method covers seen points on the shipped scenes under a sun";
}

class BodyOnScene : public ::testing::TestWithParam<std::string> {};

TEST_P(BodyOnScene, ThreeKernelsAgreeAndBodyContainsTheVisibleRegion) {
    const ShadowInputs in = gather_inputs(load_scene(GetParam()));
    const BodyInput input{in.frustum, in.scene_bounds, in.light.homogeneous()};
    const IntersectionBody exact = intersection_body(input, BodyKernel::epeck);
    const IntersectionBody fast = intersection_body(input, BodyKernel::float_clipper);
    const IntersectionBody inexact = intersection_body(input, BodyKernel::epick);
    ASSERT_FALSE(exact.body.empty());
    const double volume = exact.body.volume();
    EXPECT_NEAR(fast.body.volume(), volume, 1e-4 * volume);
    EXPECT_NEAR(inexact.body.volume(), volume, 1e-4 * volume);
    EXPECT_NEAR(fast.visible.volume(), exact.visible.volume(), 1e-4 * exact.visible.volume());

    const double tol = 1e-9 * in.scene_bounds.diagonal();
    for (const IntersectionBody* b : {&exact, &fast, &inexact}) {
        EXPECT_TRUE(is_closed(b->body));
        EXPECT_TRUE(is_convex(b->body, tol));
        for (const glm::dvec3& v : fast.visible.vertices)  // V ⊂ B
            for (const PolyFace& f : b->body.faces) ASSERT_LE(f.plane.signed_distance(v), tol);
        EXPECT_TRUE(in.scene_bounds.contains(b->body.bounds().min, tol));  // B ⊂ S
        EXPECT_TRUE(in.scene_bounds.contains(b->body.bounds().max, tol));
    }
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, BodyOnScene, ::testing::ValuesIn(shipped_scenes()),
                         [](const auto& info) { return std::filesystem::path(info.param).stem().string(); });

TEST(Focused, EmptyBodyIsANamedFallbackNotANaN) {
    Scene scene = random_town(20, 100.0, 1);
    scene.camera.position = {0, 500, 0};  // far above the scene, looking up: nothing visible
    scene.camera.target = {0, 600, 0};
    scene.camera.up = {0, 0, 1};
    const ShadowInputs in = gather_inputs(scene);
    const ShadowSetup setup = run(*find_method("focused"), in);
    EXPECT_TRUE(has_note(setup.fallbacks, NoteKind::empty_body)) << describe(setup.fallbacks);
    EXPECT_TRUE(finite(setup.maps.at(0).world_to_uvz));
}

TEST(Focused, IsTighterThanUniformWhenTheViewSeesPartOfTheScene) {
    Scene scene = random_town(200, 400.0, 3);
    scene.camera.position = {0, 2, 150};
    scene.camera.target = {0, 2, 140};
    scene.camera.far = 60;
    const ShadowInputs in = gather_inputs(scene);
    const glm::dmat4 u = run(*find_method("uniform"), in).maps[0].world_to_uvz;
    const glm::dmat4 f = run(*find_method("focused"), in).maps[0].world_to_uvz;
    // Texels per world unit: the focused map's scale in x and y is larger.
    const double uniform_scale =
        glm::length(glm::dvec3(u[0][0], u[1][0], u[2][0])) * glm::length(glm::dvec3(u[0][1], u[1][1], u[2][1]));
    const double focused_scale =
        glm::length(glm::dvec3(f[0][0], f[1][0], f[2][0])) * glm::length(glm::dvec3(f[0][1], f[1][1], f[2][1]));
    EXPECT_GT(focused_scale, 4.0 * uniform_scale);
}

TEST(Settings, UnknownKeyAndBadValuesAreNamed) {
    const Method& focused = *find_method("focused");
    EXPECT_THROW(resolve_settings("focused", focused.settings, {{"kernel", "exactish"}}), std::invalid_argument);
    try {
        resolve_settings("focused", focused.settings, {{"colour", "red"}});
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("colour"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("kernel"), std::string::npos);
    }
}
