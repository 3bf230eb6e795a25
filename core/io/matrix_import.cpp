#include "io/matrix_import.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <nlohmann/json.hpp>

namespace shadowlab {
namespace {

using Json = nlohmann::json;

constexpr size_t kEntries = 16;
// Below this share of Hadamard's bound |det| counts as 0 (see `singular`).
constexpr double kSingularRatio = 1e-12;

// Every refusal: one line naming the file, where in it, and what is wrong.
[[noreturn]] void refuse(const std::string& file, const std::string& where, const std::string& problem) {
    throw std::invalid_argument((file.empty() ? std::string("<matrices>") : file) + ": " +
                                (where.empty() ? "" : where + ": ") + problem);
}

// |det| against Hadamard's bound, the product of the column lengths: scale-free, so the matrix of a
// small, far scene (large translations) passes as a near one does, and a flattened one does not.
bool singular(const glm::dmat4& m) {
    double bound = 1.0;
    for (int c = 0; c < 4; ++c) bound *= glm::length(m[c]);
    return !(std::abs(glm::determinant(m)) > kSingularRatio * bound);
}

// The 16 numbers in reading order as the column-vector matrix they lay out.
glm::dmat4 laid_out(const std::vector<double>& numbers, MatrixStorage storage, const std::string& file,
                    const std::string& where) {
    if (numbers.size() != kEntries) refuse(file, where, "expected 16 numbers, got " + std::to_string(numbers.size()));
    glm::dmat4 m;
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) (storage == MatrixStorage::column_major ? m[a][b] : m[b][a]) = numbers[4 * a + b];
    if (singular(m)) refuse(file, where, "singular matrix (determinant 0): no light projection");
    return m;
}

// ---- Shader text ----

// The text with its // and /* */ comments blanked, newlines kept so that lines still count.
std::string without_comments(std::string text) {
    for (size_t i = 0; i + 1 < text.size(); ++i) {
        const bool line = text.compare(i, 2, "//") == 0, block = text.compare(i, 2, "/*") == 0;
        if (!line && !block) continue;
        const size_t end = line ? text.find('\n', i) : text.find("*/", i + 2);
        const size_t stop = end == std::string::npos ? text.size() : (line ? end : end + 2);
        for (size_t k = i; k < stop; ++k)
            if (text[k] != '\n') text[k] = ' ';
        i = stop - 1;
    }
    return text;
}

// A literal's number: a float literal with its language's suffix (f, lf, h) or none; nullopt
// for anything else. Non-finite values come back as read.
std::optional<double> literal_value(std::string token) {
    for (const std::string suffix : {"lf", "LF", "f", "F", "h", "H"})
        if (token.size() > suffix.size() && token.ends_with(suffix) &&
            (std::isdigit(token[token.size() - suffix.size() - 1]) || token[token.size() - suffix.size() - 1] == '.')) {
            token.resize(token.size() - suffix.size());
            break;
        }
    const char* begin = token.data() + (token.starts_with('+') ? 1 : 0);
    double value = NAN;
    const auto [end, error] = std::from_chars(begin, token.data() + token.size(), value);
    if (end != token.data() + token.size()) return std::nullopt;
    if (error == std::errc::result_out_of_range) return INFINITY;
    if (error != std::errc()) return std::nullopt;
    return value;
}

// The numbers between the bracket at `open` and its partner; vector constructors inside (HLSL's
// float4x4(float4(...), ...), GLSL's mat4(vec4(...), ...)) are read through.
std::vector<double> bracket_numbers(const std::string& text, size_t open, const std::string& file,
                                    const std::string& where) {
    static const std::regex separators(R"([\s,(){}\[\]]+)");
    static const std::vector<std::string> vector_types{"vec4", "dvec4", "float4", "double4", "half4"};
    int depth = 0;
    size_t close = open;
    for (; close < text.size(); ++close) {
        depth += text[close] == '(' || text[close] == '{';
        depth -= text[close] == ')' || text[close] == '}';
        if (depth == 0) break;
    }
    if (close == text.size()) refuse(file, where, "no closing bracket");
    const std::string body = text.substr(open + 1, close - open - 1);
    std::vector<double> numbers;
    for (std::sregex_token_iterator it(body.begin(), body.end(), separators, -1), end; it != end; ++it) {
        const std::string token = *it;
        if (token.empty() || std::find(vector_types.begin(), vector_types.end(), token) != vector_types.end()) continue;
        const std::optional<double> value = literal_value(token);
        if (!value) refuse(file, where, "'" + token + "' is not a number");
        if (!std::isfinite(*value)) refuse(file, where, "'" + token + "' is not a finite number");
        numbers.push_back(*value);
    }
    return numbers;
}

// Every match of `literal` (ending at its opening bracket) read as one matrix.
std::vector<glm::dmat4> shader_matrices(const std::string& text, const std::regex& literal, MatrixStorage storage,
                                        const std::string& file) {
    std::vector<glm::dmat4> matrices;
    for (std::sregex_iterator it(text.begin(), text.end(), literal), end; it != end; ++it) {
        const size_t open = it->position() + it->length() - 1;
        const auto line = 1 + std::count(text.begin(), text.begin() + it->position(), '\n');
        const std::string where = "matrix " + std::to_string(matrices.size()) + " (line " + std::to_string(line) + ")";
        matrices.push_back(laid_out(bracket_numbers(text, open, file, where), storage, file, where));
    }
    return matrices;
}

EngineMatrices parse_shader(const std::string& source, MatrixStorage storage, const std::string& file) {
    const std::string text = without_comments(source);
    // GLSL constructs a mat4 column by column; HLSL's initializer lists a float4x4 row by row.
    static const std::regex glsl(R"(\bd?mat4(?:x4)?\s*\()"), hlsl(R"(\b(?:float|double|half)4x4\b[^;{(]*[{(])");
    const bool is_glsl = std::regex_search(text, glsl);
    if (storage == MatrixStorage::automatic) storage = is_glsl ? MatrixStorage::column_major : MatrixStorage::row_major;
    EngineMatrices out{.clip_from_world = shader_matrices(text, is_glsl ? glsl : hlsl, storage, file)};
    if (out.clip_from_world.empty())
        refuse(file, "", "no matrix found: expected GLSL mat4(...), HLSL float4x4 ... = {...}, or a JSON object");
    return out;
}

// ---- JSON ----

std::vector<double> json_numbers(const Json& array, const std::string& file, const std::string& where) {
    if (!array.is_array()) refuse(file, where, "expected an array of numbers, got " + array.dump());
    std::vector<double> numbers;
    for (const Json& x : array) {
        if (!x.is_number() || !std::isfinite(x.get<double>()))
            refuse(file, where, "expected finite numbers, got " + x.dump());
        numbers.push_back(x.get<double>());
    }
    return numbers;
}

// 16 numbers in a row (their storage named), or 4 arrays of 4 (rows, unless named columns).
glm::dmat4 json_matrix(const Json& entry, MatrixStorage storage, const std::string& file, const std::string& where) {
    const bool nested = entry.is_array() && !entry.empty() && entry[0].is_array();
    if (!nested) {
        if (storage == MatrixStorage::automatic)
            refuse(file, where,
                   "16 numbers in a row: name their storage (setting storage=column_major or row_major), or give 4 "
                   "rows of 4");
        return laid_out(json_numbers(entry, file, where), storage, file, where);
    }
    if (entry.size() != 4) refuse(file, where, "expected 4 arrays of 4 numbers, got " + std::to_string(entry.size()));
    std::vector<double> numbers;
    for (size_t i = 0; i < 4; ++i) {
        const std::vector<double> part = json_numbers(entry[i], file, where + "[" + std::to_string(i) + "]");
        if (part.size() != 4)
            refuse(file, where + "[" + std::to_string(i) + "]",
                   "expected 4 numbers, got " + std::to_string(part.size()));
        numbers.insert(numbers.end(), part.begin(), part.end());
    }
    return laid_out(numbers, storage == MatrixStorage::automatic ? MatrixStorage::row_major : storage, file, where);
}

std::vector<glm::dvec4> json_tiles(const Json& tiles, size_t count, const std::string& file) {
    if (!tiles.is_array() || tiles.size() != count)
        refuse(file, "tiles", "expected one tile [u0, v0, u1, v1] per matrix (" + std::to_string(count) + ")");
    std::vector<glm::dvec4> out;
    for (size_t k = 0; k < count; ++k) {
        const std::string where = "tiles[" + std::to_string(k) + "]";
        const std::vector<double> t = json_numbers(tiles[k], file, where);
        if (t.size() != 4 || !(0.0 <= t[0] && t[0] < t[2] && t[2] <= 1.0 && 0.0 <= t[1] && t[1] < t[3] && t[3] <= 1.0))
            refuse(file, where, "expected [u0, v0, u1, v1] with 0 <= u0 < u1 <= 1 and 0 <= v0 < v1 <= 1");
        out.push_back({t[0], t[1], t[2], t[3]});
    }
    return out;
}

std::vector<double> json_splits(const Json& splits, size_t count, const std::string& file) {
    const std::vector<double> depths = json_numbers(splits, file, "split_depths");
    if (depths.size() != count + 1 || depths.front() < 0.0 || !std::is_sorted(depths.begin(), depths.end()) ||
        std::adjacent_find(depths.begin(), depths.end()) != depths.end())
        refuse(file, "split_depths", "expected " + std::to_string(count + 1) + " increasing view depths from >= 0");
    return depths;
}

EngineMatrices parse_json(const std::string& text, MatrixStorage storage, const std::string& file) {
    Json json;
    try {
        json = Json::parse(text);
    } catch (const Json::parse_error& e) {
        refuse(file, "", std::string("malformed JSON: ") + e.what());
    }
    if (!json.is_object()) refuse(file, "", "expected a JSON object with \"matrices\"");
    for (const auto& item : json.items())
        if (item.key() != "matrices" && item.key() != "tiles" && item.key() != "split_depths")
            refuse(file, item.key(), "unknown key; allowed: matrices, tiles, split_depths");
    const Json& matrices = json.contains("matrices") ? json["matrices"] : Json();
    if (!matrices.is_array() || matrices.empty()) refuse(file, "matrices", "expected an array of one or more matrices");
    EngineMatrices out;
    for (size_t k = 0; k < matrices.size(); ++k)
        out.clip_from_world.push_back(json_matrix(matrices[k], storage, file, "matrices[" + std::to_string(k) + "]"));
    if (json.contains("tiles")) out.tiles = json_tiles(json["tiles"], matrices.size(), file);
    if (json.contains("split_depths")) out.split_depths = json_splits(json["split_depths"], matrices.size(), file);
    return out;
}

}  // namespace

EngineMatrices parse_engine_matrices(const std::string& text, MatrixStorage storage, const std::string& file) {
    const size_t first = text.find_first_not_of(" \t\r\n");
    EngineMatrices out = first != std::string::npos && text[first] == '{' ? parse_json(text, storage, file)
                                                                          : parse_shader(text, storage, file);
    // One texture holds every map (maps/shadow_map.hpp): several need their places in it.
    if (out.clip_from_world.size() > 1 && out.tiles.empty())
        refuse(file, "",
               std::to_string(out.clip_from_world.size()) +
                   " matrices: give each its tile in the texture (JSON \"tiles\")");
    return out;
}

EngineMatrices read_engine_matrices(const std::string& file, MatrixStorage storage) {
    std::ifstream in(file);
    if (!in) refuse(file, "", "cannot open file");
    std::stringstream text;
    text << in.rdbuf();
    return parse_engine_matrices(text.str(), storage, file);
}

}  // namespace shadowlab
