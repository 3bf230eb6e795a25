// What the scene fuzzer (fuzz/scene_fuzzer.cpp) found, each kept as the smallest scene that showed it.
#include <cmath>
#include <gtest/gtest.h>

#include "registry/method.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

// XPSM gave an infinite depth-bias scale: with the eye at the height of a flat ground under an
// overhead light, every point has the same light-space depth, and step 18 divided by a zero depth
// range that its unit-cube transform had widened.
TEST(FuzzFindings, EyeAtTheHeightOfAFlatGroundUnderAnOverheadLightGivesFiniteMaps) {
    Scene scene;
    SceneObject ground;
    ground.shape = Shape::plane;
    ground.size = {20.0, 0.0, 20.0};
    scene.objects = {ground};
    scene.camera.position = {0.0, 0.0, 10.0};
    scene.camera.target = {0.0, 0.0, 0.0};
    scene.light.direction = {0.0, -1.0, 0.0};
    const ShadowInputs inputs = gather_inputs(scene);
    for (const Method* method : map_methods()) {
        const ShadowSetup setup =
            method->compute_maps(inputs, resolve_settings(method->name, method->settings, {}), nullptr);
        ASSERT_FALSE(setup.maps.empty()) << method->name;
        EXPECT_TRUE(finite(setup.maps[0].world_to_uvz)) << method->name;
        EXPECT_TRUE(std::isfinite(setup.maps[0].z_bias_scale)) << method->name;
    }
}

}  // namespace
