#include "io/matrix_export.hpp"

#include <cstdio>

#include "io/inspection_json.hpp"

namespace shadowlab {
namespace {

std::string number(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", v);
    std::string s = buffer;
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // a float literal in both languages
    return s;
}

// The 16 entries, by columns (GLSL) or by rows (HLSL).
std::string entries(const glm::dmat4& m, bool by_columns, const std::string& separator) {
    std::string out;
    for (int a = 0; a < 4; ++a) {
        out += a ? separator : "";
        for (int b = 0; b < 4; ++b) out += (b ? ", " : "") + number(by_columns ? m[a][b] : m[b][a]);
    }
    return out;
}

}  // namespace

std::string export_matrices(const std::string& method, const ShadowSetup& setup, MatrixFormat format) {
    if (format == MatrixFormat::json) {
        Json maps = Json::array();
        for (const ShadowMap& map : setup.maps) maps.push_back(to_json(map));
        return Json{{"method", method}, {"maps", maps}}.dump(2) + "\n";
    }
    const bool glsl = format == MatrixFormat::glsl;
    std::string out = "// ShadowLab, " + method + ": world (x, y, z, 1) -> (u, v, d, w); u, v, d in [0,1] after / w.\n"
                      "// Bias before the division: d = (d_pre - zBiasScale * bias) / w, bias in world units.\n";
    for (size_t i = 0; i < setup.maps.size(); ++i) {
        const std::string n = std::to_string(i);
        const glm::dmat4& m = setup.maps[i].world_to_uvz;
        out += glsl ? "const mat4 worldToUvz" + n + " = mat4(\n    " + entries(m, true, ",\n    ") + ");\n"
                    : "static const float4x4 worldToUvz" + n + " = {\n    " + entries(m, false, ",\n    ") + "};\n";
        out += (glsl ? "const float zBiasScale" : "static const float zBiasScale") + n + " = " +
               number(setup.maps[i].z_bias_scale) + ";\n";
    }
    return out;
}

}  // namespace shadowlab
