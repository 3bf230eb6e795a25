// Normalising input vectors of any finite size (math/normalize.hpp), and the camera built on it.
#include <cmath>
#include <gtest/gtest.h>

#include "math/normalize.hpp"
#include "scene/camera.hpp"

namespace shadowlab {
namespace {

void expect_near(const glm::dvec3& got, const glm::dvec3& expected, double tolerance = 1e-15) {
    EXPECT_NEAR(glm::length(got - expected), 0.0, tolerance) << "(" << got.x << ", " << got.y << ", " << got.z << ")";
}

TEST(NormalizeSafely, HugeComponentsDoNotOverflow) {
    const glm::dvec3 huge{1e308, -1e308, 0.0};
    EXPECT_NE(glm::length(glm::normalize(huge)), 1.0) << "the overflow the helper exists for";
    expect_near(normalize_safely(huge), {std::sqrt(0.5), -std::sqrt(0.5), 0.0});
}

TEST(NormalizeSafely, TinyComponentsDoNotUnderflow) {
    EXPECT_NE(glm::length(glm::normalize(glm::dvec3(1e-200, 0.0, 0.0))), 1.0) << "the underflow";
    expect_near(normalize_safely({1e-200, 1e-200, -1e-200}), glm::dvec3(1.0, 1.0, -1.0) / std::sqrt(3.0));
    expect_near(normalize_safely({0.0, 5e-324, 0.0}), {0.0, 1.0, 0.0});  // the smallest denormal
}

TEST(NormalizeSafely, OrdinaryVectorsAsGlmNormalizes) {
    for (const glm::dvec3 v : {glm::dvec3(3, 4, 0), glm::dvec3(-0.3, -1, -0.2), glm::dvec3(0, 0, -7)})
        expect_near(normalize_safely(v), glm::normalize(v));
}

// A camera built in code may give `up` at any finite size: its view and frustum are those of the
// unit up.
TEST(NormalizeSafely, CameraUpOfAnySizeGivesTheSameFrame) {
    Camera unit;
    unit.position = {3, 4, 5};
    unit.target = {-1, 2, -7};
    for (double size : {1e-300, 1e300}) {
        Camera scaled = unit;
        scaled.up = unit.up * size;
        const glm::dmat4 view = scaled.view_matrix(), expected = unit.view_matrix();
        for (int column = 0; column < 4; ++column)
            for (int row = 0; row < 4; ++row) EXPECT_NEAR(view[column][row], expected[column][row], 1e-12) << size;
        for (int i = 0; i < 8; ++i) expect_near(scaled.frustum().corners[i], unit.frustum().corners[i], 1e-12);
    }
}

}  // namespace
}  // namespace shadowlab
