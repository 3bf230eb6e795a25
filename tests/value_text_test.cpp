#include <gtest/gtest.h>

#include "io/value_text.hpp"
#include "math/matrix.hpp"

using namespace shadowlab;

TEST(ValueText, MatricesPrintRowMajorOnFourAlignedLines) {
    const glm::dmat4 m = from_rows({1, 2, 3, 4}, {5, 6, 7, 8}, {9, 10, 11, 12}, {13, 14, 15, 16});
    EXPECT_EQ(value_text(m), " 1   2   3   4\n 5   6   7   8\n 9  10  11  12\n13  14  15  16");
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
