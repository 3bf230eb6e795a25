#include "io/value_text.hpp"

#include <algorithm>
#include <cstdio>

#include "math/matrix.hpp"

namespace shadowlab {
namespace {

template <int N>
std::string vector_text(const glm::vec<N, double>& v, int digits) {
    std::string out = "[";
    for (int i = 0; i < N; ++i) out += (i ? ", " : "") + significant(v[i], digits);
    return out + "]";
}

// Row r of the matrix as the layout prints it: a row of M, or a column of M (a row of its transpose).
glm::dvec4 printed_row(const glm::dmat4& m, int r, MatrixLayout layout) {
    return layout == MatrixLayout::column_vectors ? row(m, r) : m[r];
}

}  // namespace

std::string significant(double v, int digits) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
    return buffer;
}

MatrixCells matrix_cells(const glm::dmat4& m, MatrixLayout layout, int digits) {
    MatrixCells cells;
    for (int r = 0; r < 4; ++r) {
        const glm::dvec4 x = printed_row(m, r, layout);
        for (int c = 0; c < 4; ++c) cells[r][c] = significant(x[c], digits);
    }
    return cells;
}

std::string aligned_matrix(const glm::dmat4& m, MatrixLayout layout, int digits) {
    const MatrixCells cells = matrix_cells(m, layout, digits);
    std::array<size_t, 4> width{};
    for (const auto& row : cells)
        for (size_t c = 0; c < 4; ++c) width[c] = std::max(width[c], row[c].size());
    constexpr size_t kGap = 2;  // spaces between columns
    std::string out;
    for (size_t r = 0; r < 4; ++r) {
        for (size_t c = 0; c < 4; ++c)
            out += std::string(width[c] - cells[r][c].size() + (c ? kGap : 0), ' ') + cells[r][c];
        if (r < 3) out += '\n';
    }
    return out;
}

std::string value_text(const TraceValue& value, MatrixLayout layout, int digits) {
    return std::visit(
        [&](const auto& v) -> std::string {
            using V = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<V, double>)
                return significant(v, digits);
            else if constexpr (std::is_same_v<V, std::string>)
                return v;
            else if constexpr (std::is_same_v<V, glm::dmat4>)
                return aligned_matrix(v, layout, digits);
            else
                return vector_text(v, digits);
        },
        value);
}

const char* layout_note(MatrixLayout layout) {
    return layout == MatrixLayout::row_vectors
               ? "row vectors, p' = p M: the transpose of ShadowLab's column-vector matrices, as the papers print them"
               : "column vectors, p' = M p: as ShadowLab computes them; the papers (row vectors) print the transpose";
}

}  // namespace shadowlab
