// Planar projection shadows: the seed's matrix, agreement with the exact reference on the plane,
// and the named limits.
#include <gtest/gtest.h>

#include "math/matrix.hpp"
#include "metrics/measurement.hpp"
#include "planar/planar_projection.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using shadowlab::testing::source_path;

namespace {

Measurement measure_planar(const MeasureContext& context) {
    return measure(context, *find_method("planar"), Settings{}, 0, 0.0);
}

// One box over a ground, light almost overhead.
Scene box_scene() { return load_scene(source_path("data/scenes/box_on_plane.json")); }

}  // namespace

TEST(Planar, MatrixIsTheSeedsForAPointLight) {
    const glm::dvec3 n = glm::normalize(glm::dvec3(0.2, 1, -0.1)), l(1, 7, 2);
    const double d = -0.5, nl = glm::dot(n, l);
    const glm::dmat4 m = planar_projection_matrix(glm::dvec4(n, d), glm::dvec4(l, 1));
    const glm::dmat4 seed = from_rows({nl + d - n.x * l.x, -n.y * l.x, -n.z * l.x, -d * l.x},
                                      {-n.x * l.y, nl + d - n.y * l.y, -n.z * l.y, -d * l.y},
                                      {-n.x * l.z, -n.y * l.z, nl + d - n.z * l.z, -d * l.z}, {-n.x, -n.y, -n.z, nl});
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(m[c][r], seed[c][r], 1e-12) << c << "," << r;
    // A point goes onto the plane, on its line from the light.
    const glm::dvec3 x(0.5, 2, -1), p = transform_point(m, x);
    EXPECT_NEAR(glm::dot(n, p) + d, 0.0, 1e-12);
    EXPECT_NEAR(glm::length(glm::cross(p - l, x - l)), 0.0, 1e-12);
}

TEST(Planar, DirectionalMatrixMovesPointsAlongTheLight) {
    const glm::dvec3 direction = glm::normalize(glm::dvec3(0.3, -1, 0.4));
    const glm::dmat4 m = planar_projection_matrix({0, 1, 0, 0}, glm::dvec4(-direction, 0));
    const glm::dvec3 x(2, 3, -1), p = transform_point(m, x);
    EXPECT_NEAR(p.y, 0.0, 1e-12);
    EXPECT_NEAR(glm::length(glm::cross(p - x, direction)), 0.0, 1e-12);
}

TEST(Planar, MatchesTheExactReferenceOnItsPlane) {
    for (const char* name : {"box_on_plane", "volumes", "light_overhead"}) {
        Scene scene = load_scene(source_path(std::string("data/scenes/") + name + ".json"));
        for (SceneObject& o : scene.objects) o.receives = o.shape == Shape::plane;  // judge the plane only
        const MeasureContext context = prepare_measurement(scene, 480, 270);
        const Measurement m = measure_planar(context);
        EXPECT_GT(m.error.receiver_pixels, 480u * 270u / 4) << name;
        EXPECT_LE(m.error.misclassified, 1e-3) << name;
        EXPECT_TRUE(m.limits.empty()) << name << ": " << describe(m.limits);
        EXPECT_GT(m.geometry->polygons, 0u);
    }
}

TEST(Planar, OtherReceiversAreNamedAndLeftLit) {
    const MeasureContext context = prepare_measurement(box_scene(), 320, 180);
    const Measurement m = measure_planar(context);
    ASSERT_FALSE(m.limits.empty());
    EXPECT_TRUE(shadowlab::testing::has_note(m.limits, NoteKind::not_planar_receiver)) << describe(m.limits);
    EXPECT_NE(describe(m.limits).find("'box'"), std::string::npos) << describe(m.limits);
}

TEST(Planar, CastersBelowThePlaneThrowFalseShadowsAndAreNamed) {
    Scene scene = box_scene();
    for (SceneObject& o : scene.objects) o.receives = o.shape == Shape::plane;
    scene.objects[1].position.y = -0.5;  // the box sinks halfway into the ground
    const MeasureContext context = prepare_measurement(scene, 320, 180);
    const Measurement m = measure_planar(context);
    ASSERT_FALSE(m.limits.empty());
    EXPECT_TRUE(shadowlab::testing::has_note(m.limits, NoteKind::below_plane)) << describe(m.limits);
    EXPECT_GT(m.error.false_shadow, 0.001) << "the buried half shadows the plane";
}

TEST(Planar, CastersBeyondTheLightAreClippedAndNamed) {
    Scene scene = box_scene();
    scene.light.type = LightType::point;
    scene.light.position = {0, 5, 0};
    SceneObject high = scene.objects[1];
    high.name = "high";
    high.position = {1, 8, 0};  // farther from the ground than the light
    scene.objects.push_back(high);
    for (SceneObject& o : scene.objects) o.receives = o.shape == Shape::plane;
    const MeasureContext context = prepare_measurement(scene, 320, 180);
    const Measurement m = measure_planar(context);
    ASSERT_FALSE(m.limits.empty());
    EXPECT_TRUE(shadowlab::testing::has_note(m.limits, NoteKind::beyond_light)) << describe(m.limits);
    EXPECT_LE(m.error.misclassified, 1e-3) << "clipped at w = 0: no anti-shadow";
}
