#pragma once
// 4x4 matrices as an engine writes them, in shader text (GLSL `mat4(...)`, HLSL `float4x4 ... = {...}`)
// or JSON: the reading shared by a light's matrices (matrix_import.hpp) and a camera's
// (exchange/camera_import.hpp). Every refusal is a std::invalid_argument on one line: the file, where in it
// (a matrix, a JSON field) and what is wrong.
#include <string>
#include <vector>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace shadowlab {

// How a matrix's 16 numbers are laid out, in reading order.
enum class MatrixStorage {
    automatic,     // as the text's language builds it: GLSL's mat4(...) by columns, HLSL's {...} by rows,
                   // JSON's 4 arrays of 4 by rows (as ShadowLab prints); 16 JSON numbers in a row must say
    column_major,  // the first four numbers are column 0: an OpenGL or GLM matrix in memory
    row_major,     // the first four numbers are row 0, of the matrix applied to column vectors (M p)
};

// Throws the one-line refusal "file: where: problem" (an empty `where` left out).
[[noreturn]] void refuse_matrix_text(const std::string& file, const std::string& where, const std::string& problem);

// |det| below a tiny share of Hadamard's bound (the product of the column lengths): scale-free, so
// a matrix with large translations passes as a small one does, and a flattened one does not.
bool is_singular(const glm::dmat4& m);

// One matrix of shader text: the name it is declared with ("" when none) and where it stands.
struct ShaderMatrix {
    std::string name;   // `view` in `uniform mat4 view = mat4(...)` or `float4x4 view = {...}`
    std::string where;  // "matrix 0 (line 3)"
    glm::dmat4 matrix;  // applied as M p
};

// Every GLSL mat4 / dmat4 constructor of `text`, else every HLSL float4x4 / double4x4 initializer,
// comments passed over; automatic storage reads GLSL by columns and HLSL by rows. None: empty.
std::vector<ShaderMatrix> shader_matrices(const std::string& text, MatrixStorage storage, const std::string& file);

// Whether `text` is JSON rather than shader text: it starts with '{'.
bool is_json_text(const std::string& text);
// `text` as a JSON object holding only the `allowed` keys.
nlohmann::json json_object(const std::string& text, const std::vector<std::string>& allowed, const std::string& file);
// A JSON array of finite numbers.
std::vector<double> json_numbers(const nlohmann::json& array, const std::string& file, const std::string& where);
// A JSON matrix: 16 numbers in a row (their storage named), or 4 arrays of 4 (rows, unless named columns).
glm::dmat4 json_matrix(const nlohmann::json& entry, MatrixStorage storage, const std::string& file,
                       const std::string& where);

// The whole text of `file`.
std::string read_matrix_file(const std::string& file);

}  // namespace shadowlab
