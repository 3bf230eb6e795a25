#pragma once
// Trace values as text, for people. Numbers with 6 significant digits, vectors in brackets,
// matrices as four bracketed rows on four lines; or, for tables, a matrix as a 4 x 4 grid of
// cells with a chosen number of significant digits, laid out as ShadowLab computes (column
// vectors, GLM: p' = M p, the projection in the last row) or as the papers print it (row
// vectors, Direct3D: p' = p M, the transpose, the projection in the last column).
#include <array>
#include <string>

#include "trace/trace.hpp"

namespace shadowlab {

enum class MatrixLayout { column_vectors, row_vectors };

std::string value_text(const TraceValue& value, MatrixLayout layout = MatrixLayout::column_vectors);

// `v` with `digits` significant digits (%g: 0.0001234, 1234, 1.234e+07).
std::string significant(double v, int digits);

// The matrix's 16 entries as text, cells[row][column] of the chosen layout.
using MatrixCells = std::array<std::array<std::string, 4>, 4>;
MatrixCells matrix_cells(const glm::dmat4& m, MatrixLayout layout, int digits);

}  // namespace shadowlab
