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

// XPSM's projection matrix (w = 1 + lengthP (unitP · xy)): ShadowLab keeps the w row last; the
// paper, with row vectors, prints the transpose, the projection vector as the last column.
TEST(ValueText, MatrixCellsAsComputedOrAsThePapersPrint) {
    const glm::dmat4 projection = from_rows({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0.123456, -0.5, 0, 1});
    const MatrixCells ours = matrix_cells(projection, MatrixLayout::column_vectors, 4);
    const MatrixCells papers = matrix_cells(projection, MatrixLayout::row_vectors, 4);
    EXPECT_EQ(ours[3][0], "0.1235");
    EXPECT_EQ(ours[0][3], "0");
    EXPECT_EQ(papers[0][3], "0.1235");
    EXPECT_EQ(papers[1][3], "-0.5");
    EXPECT_EQ(papers[3][0], "0");
    EXPECT_EQ(significant(1234567.0, 4), "1.235e+06");
}
