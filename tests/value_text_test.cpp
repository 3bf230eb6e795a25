#include <gtest/gtest.h>

#include "io/value_text.hpp"
#include "math/matrix.hpp"

using namespace shadowlab;

TEST(ValueText, MatricesPrintRowMajorOnFourLines) {
    const glm::dmat4 m = from_rows({1, 2, 3, 4}, {5, 6, 7, 8}, {9, 10, 11, 12}, {13, 14, 15, 16});
    const std::string text = value_text(m);
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 3);
    EXPECT_LT(text.find(" 4]"), text.find(" 5 "));  // the first row ends before the second starts
    EXPECT_EQ(value_text(glm::dvec3(1, 0.5, -2)), "[1, 0.5, -2]");
    EXPECT_EQ(value_text(0.1234567), "0.123457");
}
