// Exported matrices read back to the same map, in each language's own element order.
#include <regex>
#include <gtest/gtest.h>

#include "exchange/inspection_json.hpp"
#include "exchange/matrix_export.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

using namespace shadowlab;

namespace {

std::vector<double> numbers_between(const std::string& text, const std::string& open, const std::string& close) {
    const size_t begin = text.find(open) + open.size();
    const std::string body = text.substr(begin, text.find(close, begin) - begin);
    std::vector<double> out;
    const std::regex number(R"([-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)");
    for (auto it = std::sregex_iterator(body.begin(), body.end(), number); it != std::sregex_iterator(); ++it)
        out.push_back(std::stod(it->str()));
    return out;
}

ShadowSetup lispsm_setup() {
    const Method& method = *find_method("lispsm");
    return method.compute_maps(
        gather_inputs(load_scene(shadowlab::testing::source_path("data/scenes/box_on_plane.json"))),
        resolve_settings(method.name, method.settings, {}), nullptr);
}

}  // namespace

TEST(MatrixExport, GlslListsColumnsAndHlslRows) {
    const ShadowSetup setup = lispsm_setup();
    const glm::dmat4& m = setup.maps[0].world_to_uvz;
    const std::vector<double> glsl =
        numbers_between(export_matrices("lispsm", setup, MatrixFormat::glsl), "mat4 worldToUvz0 = mat4(", ");");
    const std::vector<double> hlsl =
        numbers_between(export_matrices("lispsm", setup, MatrixFormat::hlsl), "float4x4 worldToUvz0 = {", "};");
    ASSERT_EQ(glsl.size(), 16u);
    ASSERT_EQ(hlsl.size(), 16u);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            EXPECT_NEAR(glsl[4 * c + r], m[c][r], 1e-8 * (1 + std::abs(m[c][r])));
            EXPECT_NEAR(hlsl[4 * r + c], m[c][r], 1e-8 * (1 + std::abs(m[c][r])));
        }
    EXPECT_NE(export_matrices("lispsm", setup, MatrixFormat::glsl).find("zBiasScale0"), std::string::npos);
}

TEST(MatrixExport, JsonGivesTheMapsRowByRow) {
    const ShadowSetup setup = lispsm_setup();
    const Json json = Json::parse(export_matrices("lispsm", setup, MatrixFormat::json));
    EXPECT_EQ(json["method"], "lispsm");
    EXPECT_DOUBLE_EQ(json["maps"][0]["world_to_uvz"][3][2].get<double>(), setup.maps[0].world_to_uvz[2][3]);
}

// A tetrahedron's faces: each face's axis (the face_axis rule's) and its mask's half-planes exported
// beside its matrix, read back to the setup's numbers, and the rule said in words.
TEST(MatrixExport, FaceAxesAndMasksOfATetrahedronsFaces) {
    const Method& method = *find_method("tetra");
    const ShadowSetup setup =
        method.compute_maps(gather_inputs(load_scene(shadowlab::testing::source_path("data/scenes/lamp_room.json"))),
                            resolve_settings(method.name, method.settings, {}), nullptr);
    ASSERT_EQ(setup.maps.size(), 4u);
    const std::string glsl = export_matrices("tetra", setup, MatrixFormat::glsl);
    const std::string hlsl = export_matrices("tetra", setup, MatrixFormat::hlsl);
    EXPECT_NE(glsl.find("the largest dot with p - (0.0, 2.1"), std::string::npos) << glsl;
    for (size_t i = 0; i < setup.maps.size(); ++i) {
        const std::string n = std::to_string(i);
        const std::vector<double> axis = numbers_between(glsl, "const vec3 faceAxis" + n + " = vec3(", ");");
        ASSERT_EQ(axis.size(), 3u);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(axis[k], setup.maps[i].face_axis[k], 1e-8);
        const std::vector<double> mask = numbers_between(hlsl, "static const float3 mask" + n + "[3] = {", "};");
        ASSERT_EQ(mask.size(), 9u);
        for (int k = 0; k < 9; ++k) EXPECT_NEAR(mask[k], setup.maps[i].mask[k / 3][k % 3], 1e-8);
        EXPECT_NE(glsl.find("const vec3 mask" + n + "[3] = vec3[3](vec3("), std::string::npos);
    }
}
