#pragma once
// Matrices are column-vector (GLM, m[column][row]); papers and our output print them row by row.
#include <glm/glm.hpp>

namespace shadowlab {

inline glm::dmat4 from_rows(const glm::dvec4& r0, const glm::dvec4& r1, const glm::dvec4& r2, const glm::dvec4& r3) {
    return glm::transpose(glm::dmat4(r0, r1, r2, r3));
}

inline glm::dvec4 row(const glm::dmat4& m, int i) { return {m[0][i], m[1][i], m[2][i], m[3][i]}; }

inline glm::dvec3 transform_point(const glm::dmat4& m, const glm::dvec3& p) {
    const glm::dvec4 h = m * glm::dvec4(p, 1.0);
    return glm::dvec3(h) / h.w;
}

}  // namespace shadowlab
