// Tetrahedron shadow maps (Liao 2010; bgfx example 16): the closed forms of the regular tetrahedron's
// faces, the whole sphere of directions shared among them (each direction in exactly one face, inside
// that face's triangle of the texture), the four triangles tiling the square, the rasterizer drawing
// each face only in its own triangle, and the lamp room judged as the cube judges it at equal texels.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "maps/map_mask.hpp"
#include "methods/tetra.hpp"
#include "metrics/measurement.hpp"
#include "raster/depth_map.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

using SettingTexts = std::map<std::string, std::string>;

ShadowSetup tetra(const ShadowInputs& in, const SettingTexts& settings = {}) {
    const Method& m = method_or_throw("tetra");
    return m.compute_maps(in, resolve_settings("tetra", m.settings, settings), nullptr);
}

ShadowInputs lamp_room_inputs(int texture_resolution) {
    ShadowInputs in = gather_inputs(load_scene(source_path("data/scenes/lamp_room.json")));
    in.texture_resolution = texture_resolution;
    return in;
}

// n directions spread evenly over the sphere (the Fibonacci lattice): none on a face boundary but by chance.
std::vector<glm::dvec3> sphere_directions(int n) {
    std::vector<glm::dvec3> out;
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (int k = 0; k < n; ++k) {
        const double y = 1.0 - 2.0 * (k + 0.5) / n, radius = std::sqrt(1.0 - y * y);
        out.push_back({radius * std::cos(golden * k), y, radius * std::sin(golden * k)});
    }
    return out;
}

// The distance from (u, v) to the nearest edge of a map's mask, in (u, v) units (negative outside).
double inside_by(const ShadowMap& map, const glm::dvec2& uv) {
    double least = INFINITY;
    for (const glm::dvec3& half : map.mask)
        least = std::min(least, glm::dot(half, glm::dvec3(uv, 1.0)) / glm::length(glm::dvec2(half)));
    return least;
}

}  // namespace

TEST(Tetra, FaceAxesAreARegularTetrahedrons) {
    const std::array<glm::dvec3, 4> axes = tetra_face_axes();
    glm::dvec3 sum(0.0);
    for (int f = 0; f < 4; ++f) {
        EXPECT_NEAR(glm::length(axes[f]), 1.0, 1e-15);
        for (int g = f + 1; g < 4; ++g) EXPECT_NEAR(glm::dot(axes[f], axes[g]), -1.0 / 3.0, 1e-15) << f << " " << g;
        sum += axes[f];
    }
    EXPECT_NEAR(glm::length(sum), 0.0, 1e-15);
    // bgfx's and Liao's turn: two faces below the light's level, two above, none along a world axis.
    EXPECT_LT(axes[0].y, 0.0);
    EXPECT_GT(axes[1].y, 0.0);
    EXPECT_GT(axes[2].y, 0.0);
    EXPECT_LT(axes[3].y, 0.0);
}

// Each face's maps carries its axis; a point reads the face of largest (p - light) . a_f, one face per
// direction, and lands inside that face's triangle, at least `margin` texels from its edges.
TEST(Tetra, EveryDirectionInExactlyOneFaceInsideItsTriangle) {
    for (const int margin : {0, 2, 8}) {
        const int resolution = 1024;
        const ShadowInputs in = lamp_room_inputs(resolution);
        const ShadowSetup setup = tetra(in, {{"margin", std::to_string(margin)}});
        ASSERT_EQ(setup.maps.size(), 4u);
        ASSERT_EQ(setup.selection.rule, MapSelection::Rule::face_axis);
        const std::array<glm::dvec3, 4> axes = tetra_face_axes();
        std::array<int, 4> per_face{};
        const LightRange range = *in.light.range;
        for (const glm::dvec3& d : sphere_directions(20000)) {
            int nearest = 0, ties = 0;
            for (int f = 1; f < 4; ++f)
                if (glm::dot(axes[f], d) > glm::dot(axes[nearest], d)) nearest = f;
            for (int f = 0; f < 4; ++f) ties += glm::dot(axes[f], d) == glm::dot(axes[nearest], d);
            ASSERT_EQ(ties, 1) << "a direction on two faces";
            for (const double distance : {range.near, 0.5 * (range.near + range.far), range.far}) {
                const glm::dvec3 p = in.light.position + distance * d;
                ASSERT_EQ(select_map(setup, p), nearest);
                const ShadowMap& map = setup.maps[nearest];
                EXPECT_EQ(map.face_axis, axes[nearest]);
                const glm::dvec3 uvz = world_to_uvz(map, p);
                ASSERT_TRUE(in_unit_cube(uvz, 1e-9)) << uvz.x << " " << uvz.y << " " << uvz.z;
                ASSERT_GE(inside_by(map, glm::dvec2(uvz)) * resolution, margin - 1e-6) << "margin " << margin;
            }
            ++per_face[nearest];
        }
        for (int f = 0; f < 4; ++f) EXPECT_NEAR(per_face[f], 5000, 50) << "a quarter of the sphere each";
    }
}

// A margin beyond a twelfth of the texture's side would enlarge a face past twice its size: cut, by name.
TEST(Tetra, AMarginBeyondATwelfthOfTheTextureIsCutByName) {
    const ShadowSetup cut = tetra(lamp_room_inputs(240), {{"margin", "30"}});
    ASSERT_TRUE(has_note(cut.fallbacks, NoteKind::margin_reduced));
    EXPECT_TRUE(are_fallbacks(cut.fallbacks));
    const ShadowSetup most = tetra(lamp_room_inputs(240), {{"margin", "20"}});
    EXPECT_TRUE(most.fallbacks.empty());
    for (int f = 0; f < 4; ++f) EXPECT_EQ(cut.maps[f].world_to_uvz, most.maps[f].world_to_uvz) << "20 texels, R / 12";
}

// Without a margin a face's corners, the directions -a_g of the vertices opposite its neighbours, land
// on its quarter's corners; a direction on the boundary plane of two faces that unfold edge to edge
// (maps 0, 1 and 2 about the vertex -a_3 at the centre) lands on the same point of both, at the same depth.
TEST(Tetra, FacesSpanTheirQuartersAndUnfoldEdgeToEdge) {
    const ShadowInputs in = lamp_room_inputs(1024);
    const ShadowSetup setup = tetra(in, {{"margin", "0"}});
    const std::array<glm::dvec3, 4> axes = tetra_face_axes();
    const glm::dvec3 light = in.light.position;
    for (int f = 0; f < 4; ++f) {
        std::vector<glm::dvec2> corners;
        for (int g = 0; g < 4; ++g)
            if (g != f) corners.emplace_back(world_to_uvz(setup.maps[f], light - 2.0 * axes[g]));
        for (const glm::dvec2& c : corners)  // on a corner of the square or at its centre
            EXPECT_NEAR(std::min(glm::length(c - glm::dvec2(0.5)),
                                 glm::length(glm::abs(c - glm::dvec2(0.5)) - glm::dvec2(0.5))),
                        0.0, 1e-12)
                << "face " << f << ": " << c.x << " " << c.y;
    }
    EXPECT_NEAR(glm::length(glm::dvec2(world_to_uvz(setup.maps[0], light - axes[3])) - 0.5), 0.0, 1e-12);
    for (const auto& [f, g] : {std::pair{0, 1}, std::pair{1, 2}}) {
        // On the edge the faces share, between the vertices -a_h and -a_3 opposite the other two faces.
        const int h = 3 - f - g;  // the one of 0, 1, 2 that is neither f nor g
        const glm::dvec3 on_edge = light + 3.0 * glm::normalize(-0.3 * axes[h] - 0.7 * axes[3]);
        ASSERT_NEAR(glm::dot(on_edge - light, axes[f] - axes[g]), 0.0, 1e-12);
        const glm::dvec3 in_f = world_to_uvz(setup.maps[f], on_edge), in_g = world_to_uvz(setup.maps[g], on_edge);
        EXPECT_NEAR(glm::distance(in_f, in_g), 0.0, 1e-12) << "faces " << f << " and " << g;
    }
}

// The four masks cut the square into its quarters: each a quarter of its area, and every point of a
// grid off the diagonals in exactly one.
TEST(Tetra, TheFacesTrianglesTileTheSquare) {
    const ShadowSetup setup = tetra(lamp_room_inputs(1024));
    double area = 0.0;
    for (const ShadowMap& map : setup.maps) {
        ASSERT_EQ(mask_outline(map).size(), 3u);
        EXPECT_NEAR(mask_area(map), 0.25, 1e-12) << "counter-clockwise, a quarter";
        area += mask_area(map);
        EXPECT_EQ(map.viewport, glm::dvec4(0.0, 0.0, 1.0, 1.0)) << "every face over the whole texture";
    }
    EXPECT_NEAR(area, 1.0, 1e-12);
    int checked = 0;
    for (int i = 0; i < 101; ++i)
        for (int j = 0; j < 101; ++j) {
            const glm::dvec2 uv((i + 0.25) / 101.0, (j + 0.6) / 101.0);  // never on a diagonal
            int holding = 0;
            for (const ShadowMap& map : setup.maps) holding += in_mask(map, uv);
            ASSERT_EQ(holding, 1) << uv.x << " " << uv.y;
            ++checked;
        }
    EXPECT_EQ(checked, 101 * 101);
}

// A caster straddling the boundary of faces 0 and 1: each face writes it only inside its own
// triangle, each texel holding the depth of the face whose triangle holds it (the texel's point under
// that face lies on the caster). Without the masks each face's projection runs on across their
// shared half-diagonal into the other's triangle, where the nearer depth of two projections wins.
TEST(Tetra, TheRasterizerDrawsEachFaceOnlyInItsTriangle) {
    const int resolution = 256;
    const ShadowInputs in = lamp_room_inputs(resolution);
    const ShadowSetup setup = tetra(in, {{"margin", "0"}});
    const std::array<glm::dvec3, 4> axes = tetra_face_axes();
    const glm::dvec3 normal = glm::normalize(axes[0] + axes[1]);  // on the boundary plane of faces 0 and 1
    const glm::dvec3 across = glm::normalize(axes[0] - axes[1]), along = glm::cross(normal, across);
    const glm::dvec3 centre = in.light.position + 1.0 * normal;
    WorldTriangles caster{
        .vertices = {centre - 1.5 * across - 0.8 * along, centre + 1.5 * across - 0.8 * along, centre + 0.8 * along},
        .triangles = {{0, 1, 2}},
        .object = {0}};
    const DepthMap depth = rasterize_depth(caster, {true}, setup, resolution);
    std::array<int, 4> written{};
    for (int y = 0; y < resolution; ++y)
        for (int x = 0; x < resolution; ++x) {
            const double d = depth.at(x, y);
            if (!(d < 1.0)) continue;
            const glm::dvec2 uv = (glm::dvec2(x, y) + 0.5) / double(resolution);
            bool on_its_face = false;
            for (int f = 0; f < 4; ++f) {
                if (!in_mask(setup.maps[f], uv)) continue;
                const glm::dvec4 h = glm::inverse(setup.maps[f].world_to_uvz) * glm::dvec4(uv, d, 1.0);
                const double off_caster = std::abs(glm::dot(glm::dvec3(h) / h.w - centre, normal));
                if (off_caster < 1e-4) {
                    on_its_face = true;
                    ++written[f];
                }
            }
            ASSERT_TRUE(on_its_face) << "texel " << x << ", " << y;
        }
    EXPECT_GT(written[0], 200);
    EXPECT_GT(written[1], 200);
    ShadowSetup unmasked = setup;
    for (ShadowMap& map : unmasked.maps) map.mask.clear();
    const DepthMap overdrawn = rasterize_depth(caster, {true}, unmasked, resolution);
    int differ = 0;
    for (size_t i = 0; i < depth.codes.size(); ++i) differ += depth.codes[i] != overdrawn.codes[i];
    EXPECT_GT(differ, 100) << "the masks decide what each face draws";
}

// Issue 28: on the lamp room at equal texels (the cube's 3 x 2 atlas of R / 3 tiles, the tetrahedron's
// four triangles of one R x R texture) the tetrahedron misclassifies no more than the cube plus 0.1
// percentage points.
TEST(Tetra, TheLampRoomAsWellAsTheCubeAtEqualTexels) {
    const MeasureContext context = prepare_measurement(load_scene(source_path("data/scenes/lamp_room.json")), 640, 360);
    for (const int resolution : {1024, 2048}) {
        const auto measured = [&](const char* method) {
            const Method& m = method_or_throw(method);
            return measure(context, m, resolve_settings(method, m.settings, {}), resolution, -1.0);
        };
        const Measurement cube = measured("cube"), tetra = measured("tetra");
        EXPECT_TRUE(tetra.fallbacks.empty()) << describe(tetra.fallbacks);
        EXPECT_GT(tetra.error.misclassified, 0.0) << "a hard map misses some pixels";
        EXPECT_LE(tetra.error.misclassified, cube.error.misclassified + 0.001)
            << resolution << ": tetra " << tetra.error.misclassified << ", cube " << cube.error.misclassified;
    }
}
