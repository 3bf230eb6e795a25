#include "io/value_text.hpp"

#include <cstdio>

#include "math/matrix.hpp"

namespace shadowlab {
namespace {

template <int N>
std::string vector_text(const glm::vec<N, double>& v) {
    std::string out = "[";
    for (int i = 0; i < N; ++i) out += (i ? ", " : "") + significant(v[i], 6);
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

std::string value_text(const TraceValue& value, MatrixLayout layout) {
    return std::visit(
        [layout](const auto& v) -> std::string {
            using V = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<V, double>) return significant(v, 6);
            else if constexpr (std::is_same_v<V, std::string>) return v;
            else if constexpr (std::is_same_v<V, glm::dmat4>) {
                std::string out;
                for (int r = 0; r < 4; ++r) {
                    const glm::dvec4 x = printed_row(v, r, layout);
                    char line[128];
                    std::snprintf(line, sizeof line, "%s[%13.6g %13.6g %13.6g %13.6g]", r ? "\n" : "", x.x, x.y, x.z, x.w);
                    out += line;
                }
                return out;
            } else return vector_text(v);
        },
        value);
}

}  // namespace shadowlab
