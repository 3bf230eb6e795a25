#pragma once
// Trace values as text, for people: numbers with a chosen count of significant digits (few to
// read, 17 to copy: every double back exactly), vectors in brackets, and a matrix as an aligned
// 4 x 4 grid (four lines, each column right-aligned to its widest cell, so that a monospace font
// lines them up). A matrix is laid out as ShadowLab computes it (column vectors, GLM: p' = M p, the
// projection in the last row) or as the papers print it (row vectors, Direct3D: p' = p M, the
// transpose, the projection in the last column).
#include <array>
#include <string>

#include "trace/trace.hpp"

namespace shadowlab {

enum class MatrixLayout { column_vectors, row_vectors };

constexpr int kReadableDigits = 4;  // a matrix cell as shown in a grid
constexpr int kValueDigits = 6;     // numbers and vectors as printed
constexpr int kFullDigits = 17;     // to copy: a double round-trips

// `v` with `digits` significant digits (%g: 0.0001234, 1234, 1.234e+07).
std::string significant(double v, int digits);

// The matrix's 16 entries as text, cells[row][column] of the chosen layout.
using MatrixCells = std::array<std::array<std::string, 4>, 4>;
MatrixCells matrix_cells(const glm::dmat4& m, MatrixLayout layout, int digits);

// The grid: four lines of right-aligned cells, two spaces apart.
std::string aligned_matrix(const glm::dmat4& m, MatrixLayout layout, int digits);

// Any trace value: a number, a bracketed vector, an aligned matrix or the text itself.
std::string value_text(const TraceValue& value, MatrixLayout layout = MatrixLayout::column_vectors,
                       int digits = kValueDigits);

// One line saying which layout matrices are shown in, and how it relates to the other.
const char* layout_note(MatrixLayout layout);

}  // namespace shadowlab
