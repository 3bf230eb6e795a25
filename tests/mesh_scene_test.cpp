// A lone mesh becomes a scene the methods can work on: on a ground plane, in view, under a sun.
#include <gtest/gtest.h>

#include "registry/method.hpp"
#include "scene/mesh_scene.hpp"
#include "scene/scene_error.hpp"
#include "test_support.hpp"

using namespace shadowlab;

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

TEST(MeshScene, MissingFileIsNamed) {
    try {
        scene_around_mesh("/nonexistent/teapot.obj");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("teapot.obj"), std::string::npos) << e.what();
    }
}
