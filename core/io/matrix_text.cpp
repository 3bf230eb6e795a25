#include "io/matrix_text.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace shadowlab {
namespace {

using Json = nlohmann::json;

constexpr size_t kEntries = 16;
// Below this share of Hadamard's bound |det| counts as 0 (see `is_singular`).
constexpr double kSingularRatio = 1e-12;

// The 16 numbers in reading order as the column-vector matrix they lay out.
glm::dmat4 laid_out(const std::vector<double>& numbers, MatrixStorage storage, const std::string& file,
                    const std::string& where) {
    if (numbers.size() != kEntries)
        refuse_matrix_text(file, where, "expected 16 numbers, got " + std::to_string(numbers.size()));
    glm::dmat4 m;
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) (storage == MatrixStorage::column_major ? m[a][b] : m[b][a]) = numbers[4 * a + b];
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
    if (close == text.size()) refuse_matrix_text(file, where, "no closing bracket");
    const std::string body = text.substr(open + 1, close - open - 1);
    std::vector<double> numbers;
    for (std::sregex_token_iterator it(body.begin(), body.end(), separators, -1), end; it != end; ++it) {
        const std::string token = *it;
        if (token.empty() || std::find(vector_types.begin(), vector_types.end(), token) != vector_types.end()) continue;
        const std::optional<double> value = literal_value(token);
        if (!value) refuse_matrix_text(file, where, "'" + token + "' is not a number");
        if (!std::isfinite(*value)) refuse_matrix_text(file, where, "'" + token + "' is not a finite number");
        numbers.push_back(*value);
    }
    return numbers;
}

// The name a matrix is declared with: the identifier before the last '=' of its statement, which
// starts after the previous ';', '{' or '}'. "" for a constructor that is not assigned.
std::string declared_name(const std::string& text, size_t match, size_t open) {
    static const std::regex assigned(R"(([A-Za-z_]\w*)\s*=[^=]*$)");
    const size_t boundary = match == 0 ? std::string::npos : text.find_last_of(";{}", match - 1);
    const size_t start = boundary == std::string::npos ? 0 : boundary + 1;
    const std::string statement = text.substr(start, open - start);
    std::smatch name;
    return std::regex_search(statement, name, assigned) ? name[1].str() : "";
}

}  // namespace

[[noreturn]] void refuse_matrix_text(const std::string& file, const std::string& where, const std::string& problem) {
    throw std::invalid_argument((file.empty() ? std::string("<matrices>") : file) + ": " +
                                (where.empty() ? "" : where + ": ") + problem);
}

bool is_singular(const glm::dmat4& m) {
    double bound = 1.0;
    for (int c = 0; c < 4; ++c) bound *= glm::length(m[c]);
    return !(std::abs(glm::determinant(m)) > kSingularRatio * bound);
}

std::vector<ShaderMatrix> shader_matrices(const std::string& source, MatrixStorage storage, const std::string& file) {
    const std::string text = without_comments(source);
    // GLSL constructs a mat4 column by column; HLSL's initializer lists a float4x4 row by row.
    static const std::regex glsl(R"(\bd?mat4(?:x4)?\s*\()"), hlsl(R"(\b(?:float|double|half)4x4\b[^;{(]*[{(])");
    const bool is_glsl = std::regex_search(text, glsl);
    if (storage == MatrixStorage::automatic) storage = is_glsl ? MatrixStorage::column_major : MatrixStorage::row_major;
    std::vector<ShaderMatrix> matrices;
    const std::regex& literal = is_glsl ? glsl : hlsl;
    for (std::sregex_iterator it(text.begin(), text.end(), literal), end; it != end; ++it) {
        const size_t open = it->position() + it->length() - 1;  // every match ends at its opening bracket
        const auto line = 1 + std::count(text.begin(), text.begin() + it->position(), '\n');
        const std::string where = "matrix " + std::to_string(matrices.size()) + " (line " + std::to_string(line) + ")";
        matrices.push_back({.name = declared_name(text, it->position(), open),
                            .where = where,
                            .matrix = laid_out(bracket_numbers(text, open, file, where), storage, file, where)});
    }
    return matrices;
}

bool is_json_text(const std::string& text) {
    const size_t first = text.find_first_not_of(" \t\r\n");
    return first != std::string::npos && text[first] == '{';
}

Json json_object(const std::string& text, const std::vector<std::string>& allowed, const std::string& file) {
    Json json;
    try {
        json = Json::parse(text);
    } catch (const Json::parse_error& e) {
        refuse_matrix_text(file, "", std::string("malformed JSON: ") + e.what());
    }
    if (!json.is_object()) refuse_matrix_text(file, "", "expected a JSON object with \"" + allowed.front() + "\"");
    for (const auto& item : json.items())
        if (std::find(allowed.begin(), allowed.end(), item.key()) == allowed.end()) {
            std::string names;
            for (const std::string& key : allowed) names += (names.empty() ? "" : ", ") + key;
            refuse_matrix_text(file, item.key(), "unknown key; allowed: " + names);
        }
    return json;
}

std::vector<double> json_numbers(const Json& array, const std::string& file, const std::string& where) {
    if (!array.is_array()) refuse_matrix_text(file, where, "expected an array of numbers, got " + array.dump());
    std::vector<double> numbers;
    for (const Json& x : array) {
        if (!x.is_number() || !std::isfinite(x.get<double>()))
            refuse_matrix_text(file, where, "expected finite numbers, got " + x.dump());
        numbers.push_back(x.get<double>());
    }
    return numbers;
}

glm::dmat4 json_matrix(const Json& entry, MatrixStorage storage, const std::string& file, const std::string& where) {
    const bool nested = entry.is_array() && !entry.empty() && entry[0].is_array();
    if (!nested) {
        if (storage == MatrixStorage::automatic)
            refuse_matrix_text(file, where,
                               "16 numbers in a row: name their storage (setting storage=column_major or row_major), "
                               "or give 4 rows of 4");
        return laid_out(json_numbers(entry, file, where), storage, file, where);
    }
    if (entry.size() != 4)
        refuse_matrix_text(file, where, "expected 4 arrays of 4 numbers, got " + std::to_string(entry.size()));
    std::vector<double> numbers;
    for (size_t i = 0; i < 4; ++i) {
        const std::string part_where = where + "[" + std::to_string(i) + "]";
        const std::vector<double> part = json_numbers(entry[i], file, part_where);
        if (part.size() != 4)
            refuse_matrix_text(file, part_where, "expected 4 numbers, got " + std::to_string(part.size()));
        numbers.insert(numbers.end(), part.begin(), part.end());
    }
    return laid_out(numbers, storage == MatrixStorage::automatic ? MatrixStorage::row_major : storage, file, where);
}

std::string read_matrix_file(const std::string& file) {
    std::ifstream in(file);
    if (!in) refuse_matrix_text(file, "", "cannot open file");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace shadowlab
