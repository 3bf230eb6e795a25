#include "exchange/matrix_export.hpp"

#include <algorithm>
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

// A vec3 literal: GLSL's constructor or HLSL's initializer list.
std::string vec3_text(const glm::dvec3& v, bool glsl) {
    const std::string xyz = number(v.x) + ", " + number(v.y) + ", " + number(v.z);
    return glsl ? "vec3(" + xyz + ")" : "{" + xyz + "}";
}

// The face_axis rule's axis and the mask's half-planes of a map that has them.
std::string face_and_mask(const ShadowMap& map, const std::string& n, bool glsl) {
    const std::string vec3 = glsl ? "const vec3 " : "static const float3 ";
    std::string out;
    if (map.face_axis != glm::dvec3(0.0)) out += vec3 + "faceAxis" + n + " = " + vec3_text(map.face_axis, glsl) + ";\n";
    if (map.mask.empty()) return out;
    const std::string count = std::to_string(map.mask.size());
    out += vec3 + "mask" + n + "[" + count + "] = " + (glsl ? "vec3[" + count + "](" : "{");
    for (size_t k = 0; k < map.mask.size(); ++k) out += (k ? ", " : "") + vec3_text(map.mask[k], glsl);
    return out + (glsl ? ");\n" : "};\n");
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
    if (setup.selection.rule == MapSelection::Rule::face_axis)
        out += "// A point p reads the map whose faceAxisN has the largest dot with p - (" +
               number(setup.selection.centre.x) + ", " + number(setup.selection.centre.y) + ", " +
               number(setup.selection.centre.z) + "), the first on ties.\n";
    if (std::any_of(setup.maps.begin(), setup.maps.end(), [](const ShadowMap& m) { return !m.mask.empty(); }))
        out +=
            "// maskN: half-planes (a, b, c) of the map's (u, v); its casters are drawn only where every\n"
            "// a u + b v + c >= 0 (a clip distance of (a, b, c) . (u w, v w, w) each).\n";
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
        out += scalar + "zBiasScale" + n + " = " + number(map.z_bias_scale) + ";\n" + face_and_mask(map, n, glsl);
        if (setup.maps.size() > 1)
            out += vec4 + "viewport" + n + (glsl ? " = vec4(" : " = {") + number(map.viewport.x) + ", " +
                   number(map.viewport.y) + ", " + number(map.viewport.z) + ", " + number(map.viewport.w) +
                   (glsl ? ");\n" : "};\n");
    }
    return out;
}

}  // namespace shadowlab
