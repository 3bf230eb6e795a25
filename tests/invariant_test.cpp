// assert_invariant stays on in the Release build the tests run: a broken one throws, naming itself.
#include <gtest/gtest.h>

#include "math/invariant.hpp"
#include "scene/camera.hpp"

using namespace shadowlab;

TEST(Invariant, HoldingOneIsSilent) { EXPECT_NO_THROW(assert_invariant(1 + 1 == 2)); }

TEST(Invariant, BrokenOneThrowsWithItsConditionAndPlace) {
    try {
        const double f = 1.0, n = 2.0;
        assert_invariant(f > n);
        FAIL() << "a broken invariant went unnoticed";
    } catch (const InvariantBroken& broken) {
        const std::string what = broken.what();
        EXPECT_NE(what.find("invariant_test.cpp:"), std::string::npos) << what;
        EXPECT_NE(what.find("f > n"), std::string::npos) << what;
    }
}

TEST(Invariant, CameraWithFarBeforeNearIsRefusedWhereItsProjectionIsBuilt) {
    Camera camera;
    camera.near = 10.0;
    camera.far = 1.0;
    EXPECT_THROW(camera.projection_matrix(), InvariantBroken);
}
