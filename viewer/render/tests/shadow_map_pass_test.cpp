// The shadow-map pass checked on its pixels under Xvfb: shadows where the map puts them for every
// map method and technique, and the GPU lookup against the CPU lookup (core/maps/map_lookup).
#include <algorithm>
#include <map>
#include <array>
#include <iostream>
#include <tuple>
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "maps/clip_conventions.hpp"
#include "methods/uniform.hpp"
#include "metrics/shadow_error.hpp"
#include "reference/exact_shadows.hpp"
#include "registry/method.hpp"
#include "scene/scene_loader.hpp"
#include "view_test_support.hpp"
#include "views/offscreen_view.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kWidth = 480, kHeight = 270;

// Three tiles a third of the texture wide side by side, as a cube map's 3x2 atlas has them: at
// 1024 texels their edges fall mid-texel (341 1/3, 682 2/3). The uniform map thrice, chosen by view
// depth, split across the box's shadow so that each tile serves some of its edges.
ShadowSetup thirds(const ShadowInputs& inputs, const Settings& settings, Trace* trace) {
    const ShadowSetup uniform = compute_uniform(inputs, settings, trace);
    ShadowSetup setup{.fallbacks = uniform.fallbacks};
    for (int i = 0; i < 3; ++i) {
        ShadowMap map = uniform.maps.at(0);
        map.viewport = {i / 3.0, 0.0, (i + 1) / 3.0, 1.0 / 3.0};
        setup.maps.push_back(map);
    }
    const Camera& camera = inputs.camera;
    const double target = glm::length(camera.target - camera.position);
    setup.selection = {.rule = MapSelection::Rule::view_depth,
                       .eye = camera.position,
                       .view_axis = camera.view_direction(),
                       .split_depths = {0.0, target - 0.45, target + 0.45, camera.far}};
    return setup;
}

// An orthographic map along the light over the scene, its depth range 1e5 units deep: the scene
// lies near its near plane (d ≈ 1e-3), where a 16-bit step is 1.5 world units, far beyond the
// slope-scaled bias, and float32's a hundred-thousandth of one.
ShadowSetup deep_orthographic(const ShadowInputs& inputs, const Settings&, Trace*) {
    const glm::dvec3 centre = inputs.scene_bounds.center(), l = inputs.light.direction;
    const double half = inputs.scene_bounds.diagonal() / 2.0;
    const glm::dmat4 view =
        glm::lookAt(centre - 100.0 * l, centre, std::abs(l.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0));
    const glm::dmat4 clip_from_world = glm::ortho(-half, half, -half, half, 0.0, 1e5) * view;
    return {.maps = {{.world_to_uvz = uvz_from_clip({}) * clip_from_world}}};
}

}  // namespace

class CameraViewOfEachMethod : public ::testing::TestWithParam<std::string> {};

// Every map method and every geometric technique (the stencil pass).
TEST_P(CameraViewOfEachMethod, GroundUnderTheBoxIsDarkerThanGroundFarFromIt) {
    const Scene scene = floating_box(kWidth, kHeight);
    const Inspection in = inspect(scene, GetParam(), 1024);
    const RgbImage image = render_view(in, view_or_throw("camera"), {}, kWidth, kHeight);
    ASSERT_EQ(image.width, kWidth);
    const double under = brightness(image, pixel_of(scene.camera, {0.0, 0.0, 0.0}, kWidth, kHeight));
    const double away = brightness(image, pixel_of(scene.camera, {6.0, 0.0, -3.0}, kWidth, kHeight));
    EXPECT_GT(away, 80.0) << "the lit ground should be drawn";
    EXPECT_LT(under, 0.7 * away) << GetParam() << ": under the box " << under << ", away " << away;
}

INSTANTIATE_TEST_SUITE_P(AllMethods, CameraViewOfEachMethod, ::testing::ValuesIn([] {
                             std::vector<std::string> names;
                             for (const Method& m : all_methods()) names.push_back(m.name);
                             return names;
                         }()));

// Issue 5: the GPU pass and the CPU lookup agree on the visible pixels away from shadow edges, in
// every depth format (issue 26: the GPU's depth texture of the format's encoding, reversed Z drawn
// with glClipControl and read back as the CPU reads it).
class GpuAgreesWithCpu : public ::testing::TestWithParam<std::tuple<std::string, DepthFormat>> {};

TEST_P(GpuAgreesWithCpu, OnVisiblePixelsAwayFromShadowEdges) {
    const auto& [name, format] = GetParam();
    Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/" + name + ".json");
    scene.camera.aspect = static_cast<double>(kWidth) / kHeight;
    for (const std::string method : {"focused", "lispsm", "xpsm"}) {
        const Inspection in =
            inspect_scene(scene, {.method = method, .settings = depth_format_settings(format), .resolution = 1024});
        ASSERT_EQ(in.depth().format, format);
        const Agreement a = gpu_against_cpu_lookup(in, kWidth, kHeight);
        ASSERT_EQ(a.undrawn, 0u) << "the GPU drew nothing where the reference sees something";
        ASSERT_GT(a.compared, kWidth * kHeight / 4u);
        EXPECT_GE(a.share(), 0.995) << method << " on " << name << ", " << describe(format) << ": "
                                    << a.compared - a.agreed << " of " << a.compared << " pixels differ";
        RecordProperty(method + "_agreement", std::to_string(a.share()));  // in the XML report
        std::cout << method << " on " << name << ", " << describe(format) << ": GPU and CPU agree on " << a.agreed
                  << " of " << a.compared << " pixels away from edges\n";
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, GpuAgreesWithCpu,
                         ::testing::Combine(::testing::Values("box_on_plane", "default", "spot"),
                                            ::testing::ValuesIn(depth_formats())),
                         [](const auto& info) {
                             std::string name = std::get<0>(info.param) + "_" + describe(std::get<1>(info.param));
                             std::replace(name.begin(), name.end(), ' ', '_');
                             return name;
                         });

// Cascades: four maps in an atlas, chosen by view depth and crossfaded over a blend band, or by
// their tiles' bounds; tiles of two sizes; splits over the visible depths. The GPU selects, blends
// and looks up as the CPU does.
TEST(GpuAgreesWithCpuOnCascades, ByViewDepthWithABlendBandAndByTileBounds) {
    Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/default.json");
    scene.camera.aspect = static_cast<double>(kWidth) / kHeight;
    using SettingTexts = std::map<std::string, std::string>;
    for (const SettingTexts& settings :
         {SettingTexts{{"blend", "0.3"}}, SettingTexts{{"select", "tile"}}, SettingTexts{{"tiles", "1,0.5,0.5,0.25"}},
          SettingTexts{{"bounds", "visible"}, {"lambda", "1"}}}) {
        InspectionRequest request{.method = "cascades", .settings = settings, .resolution = 2048};
        const Agreement a = gpu_against_cpu_lookup(inspect_scene(scene, request), kWidth, kHeight);
        ASSERT_EQ(a.undrawn, 0u);
        ASSERT_GT(a.compared, kWidth * kHeight / 4u);
        EXPECT_GE(a.share(), 0.995) << settings.begin()->first << ": " << a.compared - a.agreed << " of " << a.compared
                                    << " pixels differ";
        std::cout << "cascades, " << settings.begin()->first << "=" << settings.begin()->second
                  << ": GPU and CPU agree on " << a.agreed << " of " << a.compared << " pixels away from edges\n";
    }
}

// Omnidirectional maps of a point light in a room: the cube's six perspective faces, the tetrahedron's
// four sharing one texture, each clipped to its triangle (its mask: clip distances on the GPU, clip
// planes on the CPU; with no margin, every read near a diagonal of the neighbour's depth), and the two
// paraboloids whose vertices the vertex shader projects (the CPU draws the same straight edges
// between projected vertices, with or without the casters split first).
TEST(GpuAgreesWithCpuOnOmniMaps, CubeTetrahedronAndDualParaboloidInTheLampRoom) {
    Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/lamp_room.json");
    scene.camera.aspect = static_cast<double>(kWidth) / kHeight;
    using SettingTexts = std::map<std::string, std::string>;
    for (const auto& [method, settings] :
         {std::pair{"cube", SettingTexts{}}, std::pair{"tetra", SettingTexts{}},
          std::pair{"tetra", SettingTexts{{"margin", "0"}}}, std::pair{"dpsm", SettingTexts{}},
          std::pair{"dpsm", SettingTexts{{"tessellate", "0.5"}}}})
        for (const DepthFormat& format : depth_formats()) {  // a paraboloid's reversed depth is its own
            InspectionRequest request{.method = method, .settings = settings, .resolution = 2048, .bias = 0.002};
            request.settings.merge(depth_format_settings(format));
            const Agreement a = gpu_against_cpu_lookup(inspect_scene(scene, request), kWidth, kHeight);
            ASSERT_EQ(a.undrawn, 0u);
            ASSERT_GT(a.compared, kWidth * kHeight / 4u);
            const std::string setting =  // (GCC 12 warns falsely of " " + a string: append)
                settings.empty() ? ""
                                 : std::string(" ").append(settings.begin()->first + "=" + settings.begin()->second);
            EXPECT_GE(a.share(), 0.995) << method << setting << ", " << describe(format) << ": "
                                        << a.compared - a.agreed << " of " << a.compared << " pixels differ";
            std::cout << method << setting << ", " << describe(format) << ": GPU and CPU agree on " << a.agreed
                      << " of " << a.compared << " pixels away from edges\n";
        }
}

// LogPSM's map bends straight edges (a log along the view after LiSPSM's perspective): the vertex
// shader projects the split casters' vertices as the CPU does (log_perspective_projection.glsl), both
// cut them at the same clip plane and both look up through the same log, in every depth format.
TEST(GpuAgreesWithCpuOnLogPsm, OnTheOverheadViewAndTheDefaultScene) {
    for (const std::string name : {"overhead_view", "default"}) {
        Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/" + name + ".json");
        scene.camera.aspect = static_cast<double>(kWidth) / kHeight;
        for (const DepthFormat& format : depth_formats()) {
            const Inspection in = inspect_scene(
                scene, {.method = "logpsm", .settings = depth_format_settings(format), .resolution = 2048});
            ASSERT_EQ(in.setup.maps.at(0).projection, Projection::log_perspective) << name;
            const Agreement a = gpu_against_cpu_lookup(in, kWidth, kHeight);
            ASSERT_EQ(a.undrawn, 0u);
            ASSERT_GT(a.compared, kWidth * kHeight / 4u);
            EXPECT_GE(a.share(), 0.995) << name << ", " << describe(format) << ": " << a.compared - a.agreed << " of "
                                        << a.compared << " pixels differ";
            std::cout << "logpsm on " << name << ", " << describe(format) << ": GPU and CPU agree on " << a.agreed
                      << " of " << a.compared << " pixels away from edges\n";
        }
    }
}

// Where the format's precision decides the verdicts: the floating box's ground casting on itself
// under a map 1e5 units deep. unorm16 rounds the ground's depth by up to 0.75 units either way, and
// where it rounds down past the bias the ground shadows itself in bands (acne) several pixels wide;
// the GPU's 16-bit texture draws the same bands, and float32 none, plain or reversed.
class GpuAgreesWithCpuOnADeepMap : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        if (!find_method("deep_orthographic"))
            register_method({.name = "deep_orthographic",
                             .title = "deep orthographic",
                             .description = "a test's own: 1e5 units of depth",
                             .compute_maps = deep_orthographic});
    }
};

TEST_F(GpuAgreesWithCpuOnADeepMap, WhereTheFormatsPrecisionMakesAcne) {
    Scene scene = floating_box(kWidth, kHeight);
    scene.objects[0].casts = true;  // the ground casts on itself
    for (const DepthFormat& format : depth_formats()) {
        const Inspection in = inspect_scene(
            scene, {.method = "deep_orthographic", .settings = depth_format_settings(format), .resolution = 1024});
        const ReferenceImage& ref = in.reference(kWidth, kHeight);
        const ShadowError& cpu = in.error(kWidth, kHeight);
        if (format.encoding == DepthEncoding::unorm16) {
            EXPECT_GT(cpu.false_shadow, 0.2) << describe(format) << ": acne on the CPU";
        } else {
            EXPECT_LT(cpu.false_shadow, 0.01) << describe(format);
        }
        const Agreement a = gpu_against_cpu_lookup(in, kWidth, kHeight);
        ASSERT_EQ(a.undrawn, 0u);
        ASSERT_GT(a.compared, kWidth * kHeight / 4u);
        EXPECT_GE(a.share(), 0.99) << describe(format) << ": " << a.compared - a.agreed << " of " << a.compared
                                   << " pixels differ";
        std::cout << "deep map, " << describe(format) << ": CPU false shadow " << 100 * cpu.false_shadow
                  << "%; GPU and CPU agree on " << a.agreed << " of " << a.compared << " pixels away from edges ("
                  << ref.width << "x" << ref.height << ")\n";
    }
}

// A million units from the origin float32 world coordinates step by 0.06 units: the Camera view
// draws relative to the eye, so the GPU still agrees with the CPU there (issue 11).
TEST(GpuAgreesWithCpuFarFromTheOrigin, OnTheSpotScene) {
    Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/spot.json");
    scene.camera.aspect = static_cast<double>(kWidth) / kHeight;
    const glm::dvec3 offset(1e6, 0.0, -1e6);
    for (SceneObject& o : scene.objects) o.position += offset;
    scene.camera.position += offset;
    scene.camera.target += offset;
    scene.light.position += offset;
    for (const std::string method : {"focused", "lispsm"}) {
        const Agreement a = gpu_against_cpu_lookup(inspect(scene, method, 1024), kWidth, kHeight);
        ASSERT_GT(a.compared, kWidth * kHeight / 4u);
        EXPECT_GE(a.share(), 0.995) << method << ": " << a.compared - a.agreed << " of " << a.compared
                                    << " pixels differ";
    }
}

// Tiles whose edges fall mid-texel are drawn where the CPU rasterizer draws them, not rounded to
// whole texels: shifted by a fraction of a texel, they flip texels along the box's silhouette.
class GpuAgreesWithCpuOnTiles : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        if (!find_method("thirds"))
            register_method(
                {.name = "thirds", .title = "thirds", .description = "a test's own", .compute_maps = thirds});
    }
};

TEST_F(GpuAgreesWithCpuOnTiles, WhoseEdgesFallMidTexel) {
    constexpr int width = 960, height = 540;  // pixels finer than the texels, so that a flipped texel shows
    const Scene scene = floating_box(width, height);
    for (int resolution : {256, 1024}) {  // tiles of 85 1/3 and 341 1/3 texels
        const Inspection in = inspect(scene, "thirds", resolution);
        const ReferenceImage& ref = in.reference(width, height);
        std::array<size_t, 3> served{};
        for (size_t i = 0; i < ref.visible.size(); ++i)
            if (ref.visible[i])
                if (const int map = select_map(in.setup, ref.position[i]); map >= 0) ++served[map];
        for (size_t pixels : served) EXPECT_GT(pixels, 1000u) << "every tile is looked up";

        const Agreement a = gpu_against_cpu_lookup(in, width, height);
        ASSERT_EQ(a.undrawn, 0u);
        ASSERT_GT(a.compared, width * height / 4u);
        EXPECT_GE(a.share(), 0.9999) << resolution << ": " << a.compared - a.agreed << " of " << a.compared
                                     << " pixels differ";
        RecordProperty("agreement_" + std::to_string(resolution), std::to_string(a.share()));
        std::cout << "thirds at " << resolution << ": GPU and CPU agree on " << a.agreed << " of " << a.compared
                  << " pixels away from edges\n";
    }
}
