// Alpha-tested casters (glTF alphaMode MASK): the texture's alpha read, the CPU raster's holes in closed
// form, the reference's rays through them, the shipped fence scene against the reference, BLEND read as
// MASK with its note, and bad texture files refused in one line.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "maps/map_lookup.hpp"
#include "maps/projection_kind.hpp"
#include "metrics/measurement.hpp"
#include "raster/depth_map.hpp"
#include "reference/ray_tracer.hpp"
#include "scene/png_alpha.hpp"
#include "scene/scene_error.hpp"
#include "scene/scene_loader.hpp"
#include "scene/tessellation.hpp"
#include "test_support.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

const std::string kFence = "data/scenes/fence.gltf";

// 4 x 3 texels, row 0 at the bottom: holes (alpha 0) at (0, 0), (2, 1), (1, 2) and (3, 2); 0.6 at
// (3, 0), above the cutoff 0.5 only with the factor 1.
std::shared_ptr<const AlphaTest> pattern_test(double factor = 1.0) {
    auto texture = std::make_shared<AlphaTexture>();
    texture->width = 4;
    texture->height = 3;
    texture->alpha = {0.0f, 1.0f, 1.0f, 0.6f,  //
                      1.0f, 1.0f, 0.0f, 1.0f,  //
                      1.0f, 0.0f, 1.0f, 0.0f};
    return std::make_shared<const AlphaTest>(AlphaTest{.texture = texture, .factor = factor, .cutoff = 0.5});
}

// A parallelogram a + s (b − a) + t (d − a), s and t in [0, 1], its texture coordinates (s, t) scaled by
// `repeat`: two triangles (a, b, c) and (a, c, d), c = b + d − a.
struct Card {
    glm::dvec3 a, b, d;
    glm::dvec2 repeat;

    glm::dvec3 c() const { return b + d - a; }
    glm::dvec2 uv(double s, double t) const { return glm::dvec2(s, t) * repeat; }

    WorldTriangles triangles(std::shared_ptr<const AlphaTest> test) const {
        WorldTriangles out;
        out.vertices = {a, b, c(), d};
        out.triangles = {{0, 1, 2}, {0, 2, 3}};
        out.object = {0, 0};
        out.alpha = {TriangleAlpha{.test = test, .uv = {uv(0, 0), uv(1, 0), uv(1, 1)}},
                     TriangleAlpha{.test = test, .uv = {uv(0, 0), uv(1, 1), uv(0, 1)}}};
        return out;
    }
    // Where the line through p and q meets the card's plane: (s, t) and the point.
    std::pair<glm::dvec2, glm::dvec3> meet(const glm::dvec3& p, const glm::dvec3& q) const {
        const glm::dvec3 n = glm::cross(b - a, d - a);
        const glm::dvec3 x = p + (q - p) * (glm::dot(n, a - p) / glm::dot(n, q - p));
        const glm::dmat3 frame(b - a, d - a, n);
        const glm::dvec3 st = glm::inverse(frame) * (x - a);
        return {glm::dvec2(st), x};
    }
};

// A spot light's perspective map: the light at the origin looking down −z, 90°, near 0.1, far 10.
ShadowMap spot_map() {
    const glm::dmat4 to_unit = glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.5)), glm::dvec3(0.5));
    ShadowMap map;
    map.world_to_uvz = to_unit * glm::perspective(glm::radians(90.0), 1.0, 0.1, 10.0);
    return map;
}

// How far t lies from the nearest whole number, in texels of a side of `size`.
double from_texel_edge(double t, int size) {
    const double x = t * size;
    return std::abs(x - std::round(x));
}

}  // namespace

TEST(AlphaTexture, NearestTexelRepeatedBeyondTheSquare) {
    const std::shared_ptr<const AlphaTest> test = pattern_test();
    EXPECT_EQ(test->texture->at({0.1, 0.1}), 0.0f);
    EXPECT_EQ(test->texture->at({0.3, 0.1}), 1.0f);
    EXPECT_EQ(test->texture->at({0.6, 0.5}), 0.0f);      // texel (2, 1)
    EXPECT_EQ(test->texture->at({1.1, 1.1}), 0.0f);      // repeated: (0, 0)
    EXPECT_EQ(test->texture->at({-0.1, -0.1}), 0.0f);    // repeated: (3, 2)
    EXPECT_TRUE(test->keeps({0.9, 0.1}));                // 0.6 >= 0.5
    EXPECT_FALSE(pattern_test(0.8)->keeps({0.9, 0.1}));  // 0.6 × 0.8 = 0.48 < 0.5
}

TEST(PngAlpha, TheFenceTextureReadsRowZeroAtTheBottom) {
    std::ifstream in(source_path("data/scenes/fence_holes.png"), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const AlphaTexture texture = decode_png_alpha(bytes, "fence_holes.png");
    ASSERT_EQ(texture.width, 64);
    ASSERT_EQ(texture.height, 40);
    // make_fence.py: the top 8 rows of the image are the rail; holes at texels 2..6 of each 8-texel cell.
    const auto at = [&](int x, int row_from_top) { return texture.alpha[(39 - row_from_top) * 64 + x]; };
    EXPECT_EQ(at(4, 3), 1.0f);       // rail
    EXPECT_EQ(at(4, 8 + 4), 0.0f);   // first row of holes
    EXPECT_EQ(at(0, 8 + 4), 1.0f);   // a bar
    EXPECT_EQ(at(8 + 3, 39), 1.0f);  // the cells' bottom bars: row 7 of a cell
    EXPECT_EQ(at(8 + 3, 38), 0.0f);  // its row 6, the holes' last
}

TEST(PngAlpha, ABadFileIsOneClearErrorNeverACrash) {
    std::ifstream in(source_path("data/scenes/fence_holes.png"), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_THROW(decode_png_alpha("GIF89a", "x.gif"), std::invalid_argument);
    int refused = 0;
    for (std::size_t cut = 8; cut < bytes.size(); cut += 7) {  // every truncation, and a byte flipped
        std::string flipped = bytes;
        flipped[cut] = static_cast<char>(flipped[cut] ^ 0x5A);
        for (const std::string& broken : {bytes.substr(0, cut), flipped}) try {
                const AlphaTexture texture = decode_png_alpha(broken, "broken.png");
                EXPECT_EQ(texture.alpha.size(), std::size_t(texture.width) * texture.height);
            } catch (const std::invalid_argument& problem) {
                EXPECT_FALSE(std::string(problem.what()).empty());
                ++refused;
            }
    }
    EXPECT_GT(refused, 20);  // the truncations at least
}

// Perspective-correct texture coordinates: each texel of a spot light's map over a tilted card with a
// repeated pattern holds the card's depth where the pattern keeps the surface and the far plane (1)
// in its holes, the card's texture coordinates found by casting the texel's ray onto its plane.
TEST(AlphaTestedRaster, TexelsOverHolesStayAtTheFarDepthInClosedForm) {
    const Card card{.a = {-2.0, -1.5, -3.0}, .b = {2.0, -1.0, -4.5}, .d = {-1.5, 2.0, -2.0}, .repeat = {2.0, 3.0}};
    const std::shared_ptr<const AlphaTest> test = pattern_test();
    const ShadowMap map = spot_map();
    const ProjectionKind& kind = projection_kind(map);
    constexpr int kResolution = 256;
    for (const DepthFormat& format :
         {DepthFormat{}, DepthFormat{.encoding = DepthEncoding::unorm24, .reversed = true}}) {
        const DepthMap depth =
            rasterize_depth(card.triangles(test), {true}, ShadowSetup{.maps = {map}}, kResolution, format);
        int holes = 0, kept = 0;
        for (int y = 0; y < kResolution; ++y)
            for (int x = 0; x < kResolution; ++x) {
                const glm::dvec2 uv((x + 0.5) / kResolution, (y + 0.5) / kResolution);
                const auto [st, point] = card.meet(kind.world_of(map, {uv, 0.2}), kind.world_of(map, {uv, 0.8}));
                const glm::dvec2 texture_uv = card.uv(st.x, st.y);
                constexpr double kMargin = 0.02;  // of a texel or of the card: rounding decides there
                const bool clear = st.x > kMargin && st.x < 1 - kMargin && st.y > kMargin && st.y < 1 - kMargin &&
                                   from_texel_edge(texture_uv.x, 4) > kMargin &&
                                   from_texel_edge(texture_uv.y, 3) > kMargin &&
                                   std::abs(st.x - st.y) > kMargin;  // the shared diagonal
                if (!clear) continue;
                if (test->keeps(texture_uv)) {
                    ++kept;
                    EXPECT_NEAR(depth.at(x, y), world_to_uvz(map, point).z, 1e-6) << x << ", " << y;
                } else {
                    ++holes;
                    EXPECT_EQ(depth.at(x, y), 1.0) << x << ", " << y;
                }
            }
        EXPECT_GT(holes, 2000);
        EXPECT_GT(kept, 4000);
    }
}

TEST(AlphaTestedRaster, WithoutAlphaTestsTheCardIsSolid) {
    const Card card{.a = {-2.0, -1.5, -3.0}, .b = {2.0, -1.0, -4.5}, .d = {-1.5, 2.0, -2.0}, .repeat = {2.0, 3.0}};
    WorldTriangles solid = card.triangles(pattern_test());
    const DepthMap holed = rasterize_depth(solid, {true}, ShadowSetup{.maps = {spot_map()}}, 128);
    solid.alpha.clear();
    const DepthMap opaque = rasterize_depth(solid, {true}, ShadowSetup{.maps = {spot_map()}}, 128);
    int covered = 0, differing = 0;
    for (std::size_t i = 0; i < opaque.codes.size(); ++i) {
        covered += opaque.codes[i] != far_code(opaque.format);
        if (holed.codes[i] != opaque.codes[i]) {
            ++differing;
            EXPECT_EQ(holed.codes[i], far_code(holed.format));  // a hole, never another depth
        }
    }
    EXPECT_GT(covered, 3000);
    EXPECT_GT(differing, covered / 5);  // 4 of 12 texels are holes
}

TEST(AlphaTestedReference, RaysPassThroughHolesAndStopOnTheSurface) {
    const Card card{.a = {-2.0, -2.0, -3.0}, .b = {2.0, -2.0, -3.0}, .d = {-2.0, 2.0, -3.0}, .repeat = {1.0, 1.0}};
    const RayTracer tracer(card.triangles(pattern_test()), {true});
    // Through the centre of texel (x, y) of the 4 × 3 pattern: the card's (s, t) = ((x + ½) / 4, (y + ½) / 3).
    const auto through = [&](int x, int y) {
        return card.a + (x + 0.5) / 4.0 * (card.b - card.a) + (y + 0.5) / 3.0 * (card.d - card.a);
    };
    int checked = 0;
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x) {
            const bool kept = pattern_test()->keeps({(x + 0.5) / 4.0, (y + 0.5) / 3.0});
            EXPECT_EQ(tracer.blocked(glm::dvec3(0.0), through(x, y), 2.0), kept) << x << ", " << y;
            EXPECT_EQ(tracer.first_hit(glm::dvec3(0.0), through(x, y), 0.0, 2.0).has_value(), kept) << x << ", " << y;
            ++checked;
        }
    EXPECT_EQ(checked, 12);
}

TEST(FenceScene, TheGltfMaterialIsAlphaTestedAndTheGroundOpaque) {
    const Scene scene = load_scene(source_path(kFence));
    const WorldTriangles triangles = tessellate(scene);
    ASSERT_EQ(triangles.alpha.size(), triangles.triangles.size());
    int tested = 0;
    for (std::size_t i = 0; i < triangles.triangles.size(); ++i) {
        const bool fence = scene.objects[triangles.object[i]].name == "fence";
        EXPECT_EQ(triangles.alpha[i].test != nullptr, fence);
        if (!fence) continue;
        ++tested;
        EXPECT_EQ(triangles.alpha[i].test->cutoff, 0.5);
        EXPECT_EQ(triangles.alpha[i].test->texture->width, 64);
        for (int k = 0; k < 3; ++k) {  // v up: the fence's top edge (y = 2.5) at v = 1
            const glm::dvec3& p = triangles.vertices[triangles.triangles[i][k]];
            EXPECT_NEAR(triangles.alpha[i].uv[k].x, (p.x + 2.0) / 4.0, 1e-6);
            EXPECT_NEAR(triangles.alpha[i].uv[k].y, p.y / 2.5, 1e-6);
        }
    }
    EXPECT_EQ(tested, 2);
    EXPECT_TRUE(scene.notes.empty());
}

// The test: at 2048² the fence's shadow matches the exact reference's holes, and the same fence
// drawn opaque into the map (the reference unchanged) does not.
TEST(FenceScene, TheMapsHolesMatchTheReferenceAndAnOpaqueFenceDoesNot) {
    MeasureContext context = prepare_measurement(load_scene(source_path(kFence)), 1280, 720);
    const Method& focused = method_or_throw("focused");
    const Settings settings = resolve_settings("focused", focused.settings, {});
    const Measurement tested = measure(context, focused, settings, 2048, -1.0);
    ASSERT_GT(tested.error.receiver_pixels, 100'000u);
    EXPECT_LT(tested.error.misclassified, 0.01);
    context.triangles.alpha.clear();
    const Measurement opaque = measure(context, focused, settings, 2048, -1.0);
    EXPECT_GT(opaque.error.misclassified, 0.02);  // of the receiver pixels, most far from the fence
    EXPECT_GT(opaque.error.false_shadow, 10.0 * tested.error.misclassified);  // the holes shadowed
    std::cout << "fence at 2048²: misclassified " << 100.0 * tested.error.misclassified << "% alpha-tested, "
              << 100.0 * opaque.error.misclassified << "% opaque\n";
}

namespace {

// The fence scene copied to a temporary folder with its material's fields changed.
std::string fence_with(const std::string& name, const nlohmann::json& material_patch) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "shadowlab_alpha_test";
    std::filesystem::create_directories(folder);
    for (const char* file : {"fence.bin", "fence_holes.png"})
        std::filesystem::copy_file(source_path(std::string("data/scenes/") + file), folder / file,
                                   std::filesystem::copy_options::overwrite_existing);
    std::ifstream in(source_path(kFence));
    nlohmann::json gltf = nlohmann::json::parse(in);
    gltf["materials"][0].merge_patch(material_patch);
    const std::filesystem::path file = folder / name;
    std::ofstream(file) << gltf.dump();
    return file.string();
}

}  // namespace

TEST(FenceScene, BlendIsReadAsMaskAtOneHalfWithItsNote) {
    const Scene scene = load_scene(fence_with("blend.gltf", {{"alphaMode", "BLEND"}, {"alphaCutoff", 0.9}}));
    ASSERT_EQ(scene.notes.size(), 1u);
    EXPECT_EQ(scene.notes[0].kind, NoteKind::blend_read_as_mask);
    EXPECT_NE(describe(scene.notes[0]).find("materials[0] \"fence\""), std::string::npos) << describe(scene.notes[0]);
    const std::vector<std::string> shown = loading_notes(scene);
    ASSERT_EQ(shown.size(), 1u);
    EXPECT_EQ(shown[0].find(to_string(NoteKind::blend_read_as_mask)), 0u);
    const WorldTriangles triangles = tessellate(scene);
    int tested = 0;
    for (const TriangleAlpha& alpha : triangles.alpha)
        if (alpha.test) {
            EXPECT_EQ(alpha.test->cutoff, 0.5);  // not the file's 0.9: BLEND has no cutoff
            ++tested;
        }
    EXPECT_EQ(tested, 2);
}

TEST(FenceScene, OpaqueMaterialsHaveNoAlphaTest) {
    const Scene scene = load_scene(fence_with("opaque.gltf", {{"alphaMode", "OPAQUE"}}));
    EXPECT_FALSE(tessellate(scene).alpha_tested());
}

// A texture left behind (a model copied without its images, as users bring them) is a named note and
// its material casts opaque; a texture that is there but not a PNG is one line naming the file and
// the field.
TEST(FenceScene, AMissingTextureCastsOpaqueByNameAndABadOneIsOneLine) {
    const std::string missing = fence_with("missing.gltf", nlohmann::json::object());
    {
        nlohmann::json gltf = nlohmann::json::parse(std::ifstream(missing));
        gltf["images"][0]["uri"] = "no_such.png";
        std::ofstream(missing) << gltf.dump();
    }
    const Scene scene = load_scene(missing);
    EXPECT_FALSE(tessellate(scene).alpha_tested());
    // Two consequences, each named: the fence casts opaque, and its colour is its factor alone.
    ASSERT_EQ(scene.notes.size(), 2u) << describe(scene.notes);
    EXPECT_EQ(scene.notes[0].kind, NoteKind::base_colour_texture_missing);
    EXPECT_NE(scene.notes[0].message.find("no_such.png not found, its base colour factor shown"), std::string::npos)
        << scene.notes[0].message;
    EXPECT_EQ(scene.notes[1].kind, NoteKind::alpha_texture_missing);
    EXPECT_NE(scene.notes[1].message.find("no_such.png not found, opaque"), std::string::npos)
        << scene.notes[1].message;
    const std::string not_png = fence_with("not_png.gltf", nlohmann::json::object());
    {
        nlohmann::json gltf = nlohmann::json::parse(std::ifstream(not_png));
        gltf["images"][0]["uri"] = "fence.bin";
        std::ofstream(not_png) << gltf.dump();
    }
    try {
        load_scene(not_png);
        ADD_FAILURE() << not_png << " was read";
    } catch (const SceneError& error) {
        EXPECT_EQ(error.json_path(), "images[0].uri");
        EXPECT_NE(error.problem().find("fence.bin: not a PNG image"), std::string::npos) << error.what();
        EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos) << error.what();
    }
}

namespace {

// The fence as an OBJ whose material's map_d is the fence's texture (its alpha channel), in a temporary
// folder: the same quad, its texture coordinates v up as OBJ gives them.
std::string fence_obj() {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "shadowlab_alpha_test";
    std::filesystem::create_directories(folder);
    std::filesystem::copy_file(source_path("data/scenes/fence_holes.png"), folder / "fence_holes.png",
                               std::filesystem::copy_options::overwrite_existing);
    std::ofstream(folder / "fence.mtl") << "newmtl fence\nKd 0.4 0.3 0.2\nmap_d fence_holes.png\n";
    std::ofstream(folder / "fence.obj") << "mtllib fence.mtl\n"
                                           "v -2 0 0\nv 2 0 0\nv 2 2.5 0\nv -2 2.5 0\n"
                                           "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                           "usemtl fence\nf 1/1 2/2 3/3 4/4\n";
    return (folder / "fence.obj").string();
}

}  // namespace

// OBJ's map_d through the importer's child process: the same holes as the glTF fence's, texel for texel.
TEST(FenceScene, AnObjMaterialsMapDCastsTheSameHoles) {
    const Scene obj = load_scene(fence_obj());
    ASSERT_EQ(obj.objects.size(), 2u);  // the ground plane a lone mesh is given, and the fence
    const SceneObject& obj_fence = obj.objects[1];
    // Assimp's default material first, then the file's.
    ASSERT_EQ(obj_fence.mesh->opacity_maps, (std::vector<std::string>{"", "fence_holes.png"}));
    ASSERT_EQ(obj_fence.material_alpha.size(), 2u);
    EXPECT_EQ(obj_fence.material_alpha[0], nullptr);
    ASSERT_NE(obj_fence.material_alpha[1], nullptr);
    EXPECT_EQ(obj_fence.material_alpha[1]->cutoff, 0.5);
    Scene gltf = load_scene(source_path(kFence));
    SceneObject& fence = gltf.objects.at(0);
    ASSERT_EQ(fence.name, "fence");
    // A spot light in front of the fence, looking at it.
    const glm::dmat4 to_unit = glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.5)), glm::dvec3(0.5));
    const ShadowSetup facing{
        .maps = {{.world_to_uvz =
                      to_unit * glm::perspective(glm::radians(60.0), 1.0, 1.0, 20.0) *
                      glm::lookAt(glm::dvec3(0.5, 1.5, 5.0), glm::dvec3(0.0, 1.25, 0.0), glm::dvec3(0.0, 1.0, 0.0))}}};
    const DepthMap from_gltf = rasterize_depth(tessellate(gltf), caster_flags(gltf), facing, 512);
    fence.mesh = obj_fence.mesh;
    fence.material_alpha = obj_fence.material_alpha;
    const WorldTriangles triangles = tessellate(gltf);
    int tested = 0;
    for (const TriangleAlpha& alpha : triangles.alpha) tested += alpha.test != nullptr;
    EXPECT_EQ(tested, 2);  // the quad, in two
    const DepthMap from_obj = rasterize_depth(triangles, caster_flags(gltf), facing, 512);
    WorldTriangles opaque = triangles;
    opaque.alpha.clear();
    const DepthMap from_opaque = rasterize_depth(opaque, caster_flags(gltf), facing, 512);
    std::size_t differing = 0, through_holes = 0;
    for (std::size_t i = 0; i < from_obj.codes.size(); ++i) {
        differing += from_obj.codes[i] != from_gltf.codes[i];
        through_holes += from_opaque.codes[i] != from_gltf.codes[i];
    }
    EXPECT_GT(through_holes, 10'000u);  // the ground seen through the holes, where an opaque fence stands
    EXPECT_LE(differing, through_holes / 100) << "texels where the OBJ's fence and the glTF's differ";
}

TEST(FenceScene, AMissingMapDIsOneLineNamingTheMeshAndTheTexture) {
    const std::filesystem::path folder = std::filesystem::path(fence_obj()).parent_path();
    std::ofstream(folder / "missing.mtl") << "newmtl fence\nmap_d no_such.png\n";
    std::ofstream(folder / "missing.obj") << "mtllib missing.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                             "usemtl fence\nf 1/1 2/2 3/3\n";
    try {
        load_scene((folder / "missing.obj").string());
        ADD_FAILURE() << "read";
    } catch (const SceneError& error) {
        EXPECT_NE(error.problem().find("map_d texture"), std::string::npos) << error.what();
        EXPECT_NE(error.problem().find("no_such.png: cannot open file"), std::string::npos) << error.what();
        EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos) << error.what();
    }
}

TEST(FenceScene, TheGeometricTechniquesNameTheirLimit) {
    const MeasureContext context = prepare_measurement(load_scene(source_path(kFence)), 160, 90);
    for (const char* name : {"volumes", "planar"}) {
        const Method& technique = method_or_throw(name);
        const Measurement m = measure(context, technique, resolve_settings(name, technique.settings, {}), 0, -1.0);
        const auto whole = std::find_if(m.limits.begin(), m.limits.end(),
                                        [](const Note& note) { return note.kind == NoteKind::alpha_tested_whole; });
        ASSERT_NE(whole, m.limits.end()) << name << ": " << describe(m.limits);
        EXPECT_EQ(whole->message, "2 alpha-tested caster triangles cast whole, holes and all");
    }
    const Scene opaque = load_scene(fence_with("opaque_limits.gltf", {{"alphaMode", "OPAQUE"}}));
    const Method& volumes = method_or_throw("volumes");
    const Measurement m = measure(prepare_measurement(opaque, 160, 90), volumes,
                                  resolve_settings("volumes", volumes.settings, {}), 0, -1);
    for (const Note& note : m.limits) EXPECT_NE(note.kind, NoteKind::alpha_tested_whole);
}
