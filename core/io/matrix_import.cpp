#include "io/matrix_import.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace shadowlab {
namespace {

using Json = nlohmann::json;

// A light's view-projection must be invertible: a flattened one projects no volume onto the map.
glm::dmat4 light_projection(const glm::dmat4& m, const std::string& file, const std::string& where) {
    if (is_singular(m)) refuse_matrix_text(file, where, "singular matrix (determinant 0): no light projection");
    return m;
}

EngineMatrices parse_shader(const std::string& text, MatrixStorage storage, const std::string& file) {
    EngineMatrices out;
    for (const ShaderMatrix& m : shader_matrices(text, storage, file))
        out.clip_from_world.push_back(light_projection(m.matrix, file, m.where));
    if (out.clip_from_world.empty())
        refuse_matrix_text(file, "",
                           "no matrix found: expected GLSL mat4(...), HLSL float4x4 ... = {...}, or a JSON object");
    return out;
}

std::vector<glm::dvec4> json_tiles(const Json& tiles, size_t count, const std::string& file) {
    if (!tiles.is_array() || tiles.size() != count)
        refuse_matrix_text(file, "tiles",
                           "expected one tile [u0, v0, u1, v1] per matrix (" + std::to_string(count) + ")");
    std::vector<glm::dvec4> out;
    for (size_t k = 0; k < count; ++k) {
        const std::string where = "tiles[" + std::to_string(k) + "]";
        const std::vector<double> t = json_numbers(tiles[k], file, where);
        if (t.size() != 4 || !(0.0 <= t[0] && t[0] < t[2] && t[2] <= 1.0 && 0.0 <= t[1] && t[1] < t[3] && t[3] <= 1.0))
            refuse_matrix_text(file, where, "expected [u0, v0, u1, v1] with 0 <= u0 < u1 <= 1 and 0 <= v0 < v1 <= 1");
        out.push_back({t[0], t[1], t[2], t[3]});
    }
    return out;
}

std::vector<double> json_splits(const Json& splits, size_t count, const std::string& file) {
    const std::vector<double> depths = json_numbers(splits, file, "split_depths");
    if (depths.size() != count + 1 || depths.front() < 0.0 || !std::is_sorted(depths.begin(), depths.end()) ||
        std::adjacent_find(depths.begin(), depths.end()) != depths.end())
        refuse_matrix_text(file, "split_depths",
                           "expected " + std::to_string(count + 1) + " increasing view depths from >= 0");
    return depths;
}

EngineMatrices parse_json(const std::string& text, MatrixStorage storage, const std::string& file) {
    const Json json = json_object(text, {"matrices", "tiles", "split_depths", "camera"}, file);
    const Json& matrices = json.contains("matrices") ? json["matrices"] : Json();
    if (!matrices.is_array() || matrices.empty())
        refuse_matrix_text(file, "matrices", "expected an array of one or more matrices");
    EngineMatrices out;
    for (size_t k = 0; k < matrices.size(); ++k) {
        const std::string where = "matrices[" + std::to_string(k) + "]";
        out.clip_from_world.push_back(light_projection(json_matrix(matrices[k], storage, file, where), file, where));
    }
    if (json.contains("tiles")) out.tiles = json_tiles(json["tiles"], matrices.size(), file);
    if (json.contains("split_depths")) out.split_depths = json_splits(json["split_depths"], matrices.size(), file);
    return out;
}

}  // namespace

EngineMatrices parse_engine_matrices(const std::string& text, MatrixStorage storage, const std::string& file) {
    EngineMatrices out = is_json_text(text) ? parse_json(text, storage, file) : parse_shader(text, storage, file);
    // One texture holds every map (maps/shadow_map.hpp): several need their places in it.
    if (out.clip_from_world.size() > 1 && out.tiles.empty())
        refuse_matrix_text(file, "",
                           std::to_string(out.clip_from_world.size()) +
                               " matrices: give each its tile in the texture (JSON \"tiles\")");
    return out;
}

EngineMatrices read_engine_matrices(const std::string& file, MatrixStorage storage) {
    return parse_engine_matrices(read_matrix_file(file), storage, file);
}

}  // namespace shadowlab
