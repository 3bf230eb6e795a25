// A lone mesh becomes a scene the methods can work on: framed by the camera, its shadow thrown into
// view by the sun, on a ground that holds the shadow; all of it moving and scaling with the mesh.
#include <numbers>
#include <gtest/gtest.h>

#include "registry/method.hpp"
#include "scene/mesh_scene.hpp"
#include "scene/scene_error.hpp"
#include "test_support.hpp"

using namespace shadowlab;

namespace {

// Bounds of three shapes a model comes in: a cube, a tower and a flat terrain, away from the origin.
std::vector<Aabb> model_shapes() {
    const glm::dvec3 at(12.0, -3.0, 40.0);
    return {{.min = at, .max = at + glm::dvec3(1.0)},
            {.min = at, .max = at + glm::dvec3(1.0, 4.0, 0.7)},
            {.min = at, .max = at + glm::dvec3(400.0, 30.0, 380.0)}};
}

// Normalized device coordinates, each in [-1, 1] inside the view (depth too, between near and far).
glm::dvec3 ndc_of(const Camera& camera, const glm::dvec3& world) {
    const glm::dvec4 clip = camera.projection_matrix() * camera.view_matrix() * glm::dvec4(world, 1.0);
    return glm::dvec3(clip) / clip.w;
}

bool in_view(const Camera& camera, const glm::dvec3& world) {
    const glm::dvec3 ndc = ndc_of(camera, world);
    return glm::all(glm::lessThanEqual(glm::abs(ndc), glm::dvec3(1.0)));
}

// Points over the sphere around the bounds (a Fibonacci lattice).
std::vector<glm::dvec3> sphere_points(const Aabb& box) {
    std::vector<glm::dvec3> points;
    const int count = 400;
    for (int i = 0; i < count; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / count, ring = std::sqrt(1.0 - y * y);
        const double turn = i * std::numbers::pi * (3.0 - std::sqrt(5.0));
        points.push_back(box.center() +
                         0.5 * box.diagonal() * glm::dvec3(ring * std::cos(turn), y, ring * std::sin(turn)));
    }
    return points;
}

// Where a directional light throws a point on the plane y = ground_y.
glm::dvec3 shadow_of(const glm::dvec3& point, const glm::dvec3& direction, double ground_y) {
    return point + (ground_y - point.y) / direction.y * direction;
}

}  // namespace

TEST(MeshScene, MeshStandsOnTheGroundInFrontOfTheCamera) {
    const Scene scene = scene_around_mesh(shadowlab::testing::source_path("data/meshes/tetrahedron.obj"));
    ASSERT_EQ(scene.objects.size(), 2u);
    const Aabb mesh = scene.objects[1].world_bounds();
    EXPECT_DOUBLE_EQ(scene.objects[0].world_bounds().min.y, mesh.min.y);
    EXPECT_TRUE(scene.camera.frustum().contains(0.5 * (mesh.min + mesh.max)));
    const Method& focused = *find_method("focused");
    const ShadowSetup setup =
        focused.compute_maps(gather_inputs(scene), resolve_settings("focused", focused.settings, {}), nullptr);
    EXPECT_TRUE(setup.fallbacks.empty());
}

// The bounds' sphere lies wholly in the view and spans at least half of its height (the narrower
// side at 16:9), seen from 25-35° above.
TEST(MeshScene, TheCameraFramesTheBoundingSphereLookingDownAboutThirtyDegrees) {
    for (const Aabb& box : model_shapes()) {
        const Camera camera = camera_framing(box);
        double low = 1.0, high = -1.0;
        for (const glm::dvec3& p : sphere_points(box)) {
            EXPECT_TRUE(in_view(camera, p)) << "a point of the sphere out of view: " << ndc_of(camera, p).x << " "
                                            << ndc_of(camera, p).y << " " << ndc_of(camera, p).z;
            low = std::min(low, ndc_of(camera, p).y);
            high = std::max(high, ndc_of(camera, p).y);
        }
        EXPECT_GE(high - low, 0.5 * 2.0) << "the sphere spans too little of the view's height";
        const double down = glm::degrees(std::asin(-camera.view_direction().y));
        EXPECT_GE(down, 25.0);
        EXPECT_LE(down, 35.0);
        EXPECT_LT(camera.far / camera.near, 100.0);  // depth precision to spare
    }
}

// The shadow of every corner of the bounds falls on the ground and in the camera's view, away from
// the camera (the sun is behind it); the ground is sized by that shadow, not by many times the model.
TEST(MeshScene, TheBoundsShadowFallsOnTheGroundAndInView) {
    for (const Aabb& box : model_shapes()) {
        const Camera camera = camera_framing(box);
        const Light sun = sun_beside(camera);
        ASSERT_TRUE(sun.is_directional());
        const SceneObject ground = ground_under(box, sun);
        const Aabb plane = ground.world_bounds();
        EXPECT_DOUBLE_EQ(plane.min.y, box.min.y);
        for (const glm::dvec3& corner : box.corners()) {
            const glm::dvec3 shadow = shadow_of(corner, sun.direction, box.min.y);
            EXPECT_TRUE(plane.contains(shadow, 1e-9 * box.diagonal())) << "a corner's shadow off the ground";
            EXPECT_TRUE(in_view(camera, shadow)) << "a corner's shadow out of view";
        }
        for (const glm::dvec3& corner : plane.corners()) {  // the whole ground within the depth range
            const double depth = -(camera.view_matrix() * glm::dvec4(corner, 1.0)).z;
            EXPECT_GT(depth, camera.near);
            EXPECT_LT(depth, camera.far);
        }
        const glm::dvec2 sun_heading(sun.direction.x, sun.direction.z);
        const glm::dvec2 camera_heading(camera.view_direction().x, camera.view_direction().z);
        EXPECT_GT(glm::dot(sun_heading, camera_heading), 0.0) << "the shadows fall toward the camera";
        EXPECT_LT(glm::degrees(std::asin(-sun.direction.y)), 80.0) << "a sun from straight above hides the shadows";
        EXPECT_LT(std::max(ground.size.x, ground.size.z), 2.0 * box.diagonal());
    }
}

// A lamp no higher than the model throws shadows toward the horizon: the ground still ends.
TEST(MeshScene, UnderALowLampTheGroundStopsAtThreeRadii) {
    const Aabb box = model_shapes()[0];
    const double radius = 0.5 * box.diagonal();
    const Light lamp{.type = LightType::point, .position = box.center() + glm::dvec3(2.0 * radius, 0.0, 0.0)};
    const SceneObject ground = ground_under(box, lamp);
    EXPECT_GT(ground.size.x, 2.0 * radius);
    EXPECT_LE(ground.size.x, 6.0 * radius + 1e-9);
    EXPECT_LE(ground.size.z, 6.0 * radius + 1e-9);
}

// The parts follow the mesh: moved by t and scaled by s about the origin, the camera, ground and
// sun are the same parts moved and scaled alike.
TEST(MeshScene, MovingOrScalingTheMeshMovesOrScalesItsParts) {
    const Aabb box = model_shapes()[1];
    const double s = 250.0;
    const glm::dvec3 t(-7e3, 35.0, 1e3);
    const Aabb moved{.min = s * box.min + t, .max = s * box.max + t};
    const Camera a = camera_framing(box), b = camera_framing(moved);
    const auto expect_moved = [&](const glm::dvec3& before, const glm::dvec3& after) {
        EXPECT_LT(glm::length(s * before + t - after), 1e-9 * s * box.diagonal());
    };
    expect_moved(a.position, b.position);
    expect_moved(a.target, b.target);
    EXPECT_NEAR(b.near, s * a.near, 1e-9 * b.near);
    EXPECT_NEAR(b.far, s * a.far, 1e-9 * b.far);
    const Light sun_a = sun_beside(a), sun_b = sun_beside(b);
    EXPECT_LT(glm::length(sun_a.direction - sun_b.direction), 1e-12);
    const SceneObject ground_a = ground_under(box, sun_a), ground_b = ground_under(moved, sun_b);
    expect_moved(ground_a.position, ground_b.position);
    EXPECT_LT(glm::length(s * ground_a.size - ground_b.size), 1e-9 * s * box.diagonal());
}

// A camera from a file (looking any way) gets a sun whose shadows fall away from it.
TEST(MeshScene, TheSunStandsBehindAnyCamera) {
    for (const glm::dvec3& position : {glm::dvec3(10, 5, 0), glm::dvec3(-3, 1, -8), glm::dvec3(0.5, 9, 0.5)}) {
        const Camera camera{.position = position, .target = {0.0, 0.0, 0.0}};
        const Light sun = sun_beside(camera);
        EXPECT_GT(glm::dot(glm::dvec2(sun.direction.x, sun.direction.z),
                           glm::dvec2(camera.view_direction().x, camera.view_direction().z)),
                  0.0);
        EXPECT_LT(sun.direction.y, 0.0);
    }
}

TEST(MeshScene, MissingFileIsNamed) {
    try {
        scene_around_mesh("/nonexistent/teapot.obj");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("teapot.obj"), std::string::npos) << e.what();
    }
}
