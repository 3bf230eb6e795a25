// The window's session without a window: a scene opened is on trial until its inspection lands;
// if it cannot be inspected, the scene before it comes back, with where "Camera in shadow" had
// moved its camera from; a scene that landed stays whatever fails after it.
#include <gtest/gtest.h>

#include <memory>

#include "model/session.hpp"

using namespace shadowlab;

namespace {

std::string scene_file(const char* name) { return std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/" + name; }

// What the window's worker would deliver for the session's scene.
std::shared_ptr<const Inspection> inspected(const Session& session) {
    return std::make_shared<const Inspection>(inspect_scene(session.scene(), {.resolution = 256}));
}

}  // namespace

TEST(Session, AnOpenedSceneThatCannotBeInspectedGivesWayToThePreviousOne) {
    Session session;
    session.open_file(scene_file("volumes.json"));
    EXPECT_EQ(session.land(inspected(session)), scene_file("volumes.json"));  // its opening completed
    const Inspection* shown = session.inspection();
    ASSERT_NE(shown, nullptr);
    const Camera outside = session.scene().camera;
    ASSERT_TRUE(session.put_camera_in_shadow(true));
    const glm::dvec3 in_shadow = session.scene().camera.position;
    ASSERT_NE(in_shadow, outside.position);

    session.open_file(scene_file("box_on_plane.json"));
    EXPECT_EQ(session.scene().name, "box_on_plane");
    EXPECT_TRUE(session.fail());  // its inspection failed: rolled back
    EXPECT_EQ(session.scene().name, "volumes");
    EXPECT_EQ(session.scene().camera.position, in_shadow);
    EXPECT_EQ(session.inspection(), shown);
    ASSERT_TRUE(session.put_camera_in_shadow(false));  // where the camera was before it moved into shadow
    EXPECT_EQ(session.scene().camera.position, outside.position);
}

TEST(Session, ASceneThatLandedStaysWhenALaterChangeFails) {
    Session session;
    session.open_file(scene_file("box_on_plane.json"));
    session.land(inspected(session));
    session.turn_light(glm::normalize(glm::dvec3(0.3, -1.0, 0.2)));
    EXPECT_FALSE(session.fail());  // nothing on trial
    EXPECT_EQ(session.scene().name, "box_on_plane");
    EXPECT_EQ(session.scene().light.direction, glm::normalize(glm::dvec3(0.3, -1.0, 0.2)));
    EXPECT_FALSE(session.land(inspected(session)).has_value());  // no opening to complete
}

TEST(Session, AFileThatCannotBeReadLeavesTheSceneShown) {
    Session session;
    session.open_file(scene_file("box_on_plane.json"));
    session.land(inspected(session));
    EXPECT_THROW(session.open_file(std::string(SHADOWLAB_SOURCE_DIR) + "/tests/data/bad/negative_size.json"),
                 std::exception);
    EXPECT_EQ(session.scene().name, "box_on_plane");
    EXPECT_FALSE(session.fail());
}
