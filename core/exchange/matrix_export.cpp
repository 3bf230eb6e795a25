#include "exchange/matrix_export.hpp"

#include <cstdio>

#include "exchange/inspection_json.hpp"
#include "maps/projection_kind.hpp"

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

// ", centre, frame_from_world, near, far": the names of a map's parameters.
std::string parameter_names(const ProjectionKind& kind, const ShadowMap& map) {
    std::string out;
    for (const NamedValue& v : kind.parameters(map)) out += (out.empty() ? " " : ", ") + v.name;
    return out;
}

}  // namespace

std::string export_matrices(const std::string& method, const ShadowSetup& setup, MatrixFormat format) {
    if (format == MatrixFormat::json) {
        Json maps = Json::array();
        for (const ShadowMap& map : setup.maps) maps.push_back(to_json(map));
        return Json{{"method", method}, {"maps", maps}, {"selection", to_json(setup.selection)}}.dump(2) + "\n";
    }
    const bool glsl = format == MatrixFormat::glsl;
    const std::string vec4 = glsl ? "const vec4 " : "static const float4 ",
                      scalar = glsl ? "const float " : "static const float ";
    std::string out =
        "// ShadowLab, " + method +
        ": world (x, y, z, 1) -> (u, v, d, w); u, v, d in [0,1] after / w.\n"
        "// Bias as ShadowLab's lookup applies it, in world units along the light l: the depth compared\n"
        "// is the map's depth of the point moved toward the light, d = uvz(p - bias * l).z, exact under\n"
        "// any projection. zBiasScaleN is XPSM's step 18 pre-division slope, for engines that bias as\n"
        "// (d_pre - zBiasScale * bias) / w: first order only, z / near times too strong on a perspective map.\n";
    if (setup.maps.size() > 1)
        out += "// " + std::to_string(setup.maps.size()) + " maps, chosen " + to_string(setup.selection.rule) +
               "; viewportN = (u0, v0, u1, v1), the map's tile in the texture.\n";
    for (size_t i = 0; i < setup.maps.size(); ++i) {
        const std::string n = std::to_string(i);
        const ShadowMap& map = setup.maps[i];
        const ProjectionKind& kind = projection_kind(map);
        if (!kind.projective())  // no 4x4 can say it: its parameters instead
            out += "// map " + n + " is a " + kind.name + " map: see the JSON export for its" +
                   parameter_names(kind, map) + ".\n";
        else
            out += glsl ? "const mat4 worldToUvz" + n + " = mat4(\n    " + entries(map.world_to_uvz, true, ",\n    ") +
                              ");\n"
                        : "static const float4x4 worldToUvz" + n + " = {\n    " +
                              entries(map.world_to_uvz, false, ",\n    ") + "};\n";
        out += scalar + "zBiasScale" + n + " = " + number(map.z_bias_scale) + ";\n";
        if (setup.maps.size() > 1)
            out += vec4 + "viewport" + n + (glsl ? " = vec4(" : " = {") + number(map.viewport.x) + ", " +
                   number(map.viewport.y) + ", " + number(map.viewport.z) + ", " + number(map.viewport.w) +
                   (glsl ? ");\n" : "};\n");
    }
    return out;
}

}  // namespace shadowlab
