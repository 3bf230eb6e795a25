#pragma once
// An engine's light view-projection matrices, read as the engine writes them: GLSL `mat4(...)`,
// HLSL `float4x4 ... = {...}` or JSON. The reverse of exchange/matrix_export.hpp;
// maps/clip_conventions.hpp turns them into ShadowLab's world_to_uvz.
//
// The JSON schema:
//   {"matrices": [M, ...],               one or more, each 16 numbers or 4 arrays of 4
//    "tiles": [[u0, v0, u1, v1], ...],   one per matrix: its tile in the engine's texture (needed for several)
//    "split_depths": [d0, ..., dn],      optional, matrices + 1 increasing view depths: cascades
//    "camera": {...}}                    passed over: the engine's camera may share the file
//                                        (exchange/camera_import.hpp)
#include <string>
#include <vector>
#include <glm/glm.hpp>

#include "io/matrix_text.hpp"

namespace shadowlab {

struct EngineMatrices {
    std::vector<glm::dmat4> clip_from_world;  // the light view-projections, applied as M p
    std::vector<glm::dvec4> tiles;            // none, or one per matrix: (u0, v0, u1, v1)
    std::vector<double> split_depths;         // none, or one more than the matrices, increasing
};

// The matrices `text` holds: JSON when it starts with '{', else every GLSL mat4 / dmat4 constructor,
// else every HLSL float4x4 / double4x4 initializer. Throws std::invalid_argument, one line naming
// `file`, the matrix (or JSON field) and what is wrong: a count other than 16, a word or a
// non-finite number, a singular matrix, several matrices without tiles (io/matrix_text.hpp reads them).
EngineMatrices parse_engine_matrices(const std::string& text, MatrixStorage storage, const std::string& file);
// The same, read from a file.
EngineMatrices read_engine_matrices(const std::string& file, MatrixStorage storage);

}  // namespace shadowlab
