// Omnidirectional maps of spot and point lights (dpsm, cube, tetra): every visible receiver in its map,
// depth growing along the light's rays, the paraboloids' centres and rims where the closed forms
// put them, the cube's faces meeting edge to edge, the light's range used as given, and both
// covering the lamp room where one perspective map cannot.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "methods/cube.hpp"
#include "methods/dpsm.hpp"
#include "metrics/measurement.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

ShadowSetup run(const std::string& method, const ShadowInputs& in) {
    const Method& m = method_or_throw(method);
    return m.compute_maps(in, resolve_settings(method, m.settings, {}), nullptr);
}

Scene lamp_room() { return load_scene(source_path("data/scenes/lamp_room.json")); }

}  // namespace

TEST(OmniMaps, EveryVisibleReceiverLandsInItsMap) {
    for (const char* file : {"lamp_room.json", "point.json", "spot.json"}) {
        const Scene scene = load_scene(source_path(std::string("data/scenes/") + file));
        const MeasureContext context = prepare_measurement(scene, 160, 90);
        const ShadowInputs in = gather_inputs(scene);
        for (const char* method : {"dpsm", "cube", "tetra"}) {
            const ShadowSetup setup = run(method, in);
            EXPECT_TRUE(setup.fallbacks.empty()) << method << " on " << file << ": " << describe(setup.fallbacks);
            const ReferenceImage& seen = context.reference;
            for (size_t i = 0; i < seen.visible.size(); ++i) {
                if (!seen.visible[i] || !scene.objects[seen.object[i]].receives) continue;
                const int map = select_map(setup, seen.position[i]);
                ASSERT_GE(map, 0) << method << " on " << file;
                const glm::dvec3 uvz = world_to_uvz(setup.maps[map], seen.position[i]);
                ASSERT_TRUE(in_unit_cube(uvz, 1e-9))
                    << method << " on " << file << " map " << map << ": " << uvz.x << " " << uvz.y << " " << uvz.z;
                if (setup.maps[map].projection == Projection::paraboloid) {
                    ASSERT_LE(glm::length(glm::dvec2(uvz) - 0.5), 0.5 + 1e-9) << "on the disc";
                }
            }
        }
    }
}

// Along any ray from the light a point stays in one map, and its depth grows with its distance.
TEST(OmniMaps, DepthGrowsAlongEveryRayFromTheLight) {
    const ShadowInputs in = gather_inputs(lamp_room());
    std::mt19937 rng(14);
    std::normal_distribution<double> gauss;
    for (const char* method : {"dpsm", "cube", "tetra"}) {
        const ShadowSetup setup = run(method, in);
        for (int k = 0; k < 500; ++k) {
            const glm::dvec3 direction = glm::normalize(glm::dvec3(gauss(rng), gauss(rng), gauss(rng)));
            const glm::dvec3 a = in.light.position + 0.5 * direction, b = in.light.position + 4.0 * direction;
            const int map = select_map(setup, a);
            ASSERT_EQ(select_map(setup, b), map) << method;
            EXPECT_GT(world_to_uvz(setup.maps[map], b).z, world_to_uvz(setup.maps[map], a).z) << method;
        }
    }
}

// The front hemisphere looks down: straight below the light is its disc's centre, straight above the
// back disc's; a point level with the light (d.z = 0) lies on both rims, (u, v) = 1/2 + (d.x, d.y)/2.
TEST(OmniMaps, ParaboloidsPutTheAxisAtTheCentreAndTheLevelOnTheRim) {
    const ShadowInputs in = gather_inputs(lamp_room());
    const ShadowSetup setup = run("dpsm", in);
    ASSERT_EQ(setup.maps.size(), 2u);
    const glm::dvec3 light = in.light.position;
    EXPECT_NEAR(glm::length(glm::dvec2(world_to_uvz(setup.maps[0], light + glm::dvec3(0, -1, 0))) - 0.5), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(glm::dvec2(world_to_uvz(setup.maps[1], light + glm::dvec3(0, 1, 0))) - 0.5), 0.0, 1e-12);
    for (const glm::dvec3& level : {glm::dvec3(1, 0, 0), glm::dvec3(0, 0, -2), glm::dvec3(0.6, 0, 0.8)})
        for (const ShadowMap& map : setup.maps)
            EXPECT_NEAR(glm::length(glm::dvec2(world_to_uvz(map, light + level)) - 0.5), 0.5, 1e-12);
    // (1, 0, 1)/√2 in a hemisphere's frame: the disc's (0.41421, 0), so u = 1/2 + 0.41421/2.
    const glm::dmat3 world_from_frame = glm::transpose(setup.maps[0].paraboloid.frame_from_world);
    const glm::dvec3 uvz = world_to_uvz(setup.maps[0], light + world_from_frame * glm::dvec3(1, 0, 1));
    EXPECT_NEAR(2 * uvz.x - 1, 0.41421, 5e-6);
    EXPECT_NEAR(2 * uvz.y - 1, 0.0, 1e-12);
}

// A direction halfway between two faces lies on the shared edge of both; each face spans 90°.
TEST(OmniMaps, CubeFacesMeetEdgeToEdge) {
    const ShadowInputs in = gather_inputs(lamp_room());
    const ShadowSetup setup = run("cube", in);
    ASSERT_EQ(setup.maps.size(), 6u);
    const glm::dvec3 light = in.light.position;
    for (int face = 0; face < 6; ++face) {
        EXPECT_EQ(setup.maps[face].cube_face, face);
        glm::dvec3 axis(0.0);
        axis[face / 2] = face % 2 ? -1.0 : 1.0;
        EXPECT_NEAR(glm::length(glm::dvec2(world_to_uvz(setup.maps[face], light + 2.0 * axis)) - 0.5), 0.0, 1e-12);
    }
    const glm::dvec3 between_px_pz = light + glm::dvec3(1, 0.2, 1);  // x = z: the edge of faces +x (0) and +z (4)
    for (int face : {0, 4}) {
        const glm::dvec2 uv(world_to_uvz(setup.maps[face], between_px_pz));
        EXPECT_NEAR(std::min(std::abs(uv.x), std::abs(uv.x - 1)), 0.0, 1e-12) << "face " << face;
    }
}

TEST(OmniMaps, TheLightsRangeIsUsedAsGivenElseFitToTheScene) {
    Scene scene = lamp_room();
    ASSERT_TRUE(scene.light.range.has_value());
    const ShadowSetup given = run("dpsm", gather_inputs(scene));
    EXPECT_EQ(given.maps[0].paraboloid.near, scene.light.range->near);
    EXPECT_EQ(given.maps[0].paraboloid.far, scene.light.range->far);
    scene.light.range.reset();
    const ShadowInputs in = gather_inputs(scene);
    const ShadowSetup fitted = run("dpsm", in);
    for (const glm::dvec3& corner : in.scene_bounds.corners())
        EXPECT_LE(glm::distance(corner, in.light.position), fitted.maps[0].paraboloid.far);
    EXPECT_GT(fitted.maps[0].paraboloid.near, 0.0);
}

TEST(OmniMaps, ADirectionalLightTakesTheFocusedMapByName) {
    const ShadowInputs in = gather_inputs(load_scene(source_path("data/scenes/box_on_plane.json")));
    for (const char* method : {"dpsm", "cube", "tetra"}) {
        const ShadowSetup setup = run(method, in);
        EXPECT_TRUE(has_note(setup.fallbacks, NoteKind::directional_light)) << method;
        ASSERT_EQ(setup.maps.size(), 1u);
        EXPECT_EQ(setup.maps[0].projection, Projection::linear);
    }
}

// One perspective map cannot hold a room seen all around the bulb (it names the points it leaves
// out); both omnidirectional maps cover it and misclassify less (a constant bias of 2 mm).
TEST(OmniMaps, BothCoverTheLampRoomWhereOnePerspectiveMapCannot) {
    const MeasureContext context = prepare_measurement(lamp_room(), 320, 180);
    const auto measured = [&](const char* method) {
        const Method& m = method_or_throw(method);
        return measure(context, m, resolve_settings(method, m.settings, {}), 2048, 0.002);
    };
    const Measurement focused = measured("focused"), dpsm = measured("dpsm"), cube = measured("cube");
    EXPECT_TRUE(has_note(focused.fallbacks, NoteKind::behind_light));
    EXPECT_LT(dpsm.error.misclassified, 0.5 * focused.error.misclassified);
    EXPECT_LT(cube.error.misclassified, 0.5 * focused.error.misclassified);
}
