// What the views draw, checked on their pixels (under Xvfb): shadows where the map puts them, the
// map's depth image where world_to_uvz puts the caster, and the GPU pass against the CPU lookup.
#include <gtest/gtest.h>

#include "methods/method.hpp"
#include "metrics/shadow_error.hpp"
#include "reference/exact_shadows.hpp"
#include "render/offscreen_view.hpp"
#include "scene/scene_loader.hpp"

using namespace shadowlab;

namespace {

constexpr int kWidth = 480, kHeight = 270;

// A box floating over a ground plane under an almost overhead sun; the camera looks at the ground
// beneath the box from the side, so the shadow is in view and not hidden by the box.
Scene floating_box() {
    Scene scene;
    scene.name = "floating box";
    scene.camera.position = {0.0, 6.0, 12.0};
    scene.camera.target = {0.0, 0.0, 0.0};
    scene.camera.aspect = static_cast<double>(kWidth) / kHeight;
    scene.camera.near = 0.5;
    scene.camera.far = 60.0;
    scene.light.direction = glm::normalize(glm::dvec3(0.05, -1.0, 0.03));
    SceneObject ground;
    ground.name = "ground";
    ground.shape = Shape::plane;
    ground.size = {24.0, 0.0, 24.0};
    ground.casts = false;
    SceneObject box;
    box.name = "box";
    box.position = {0.0, 3.0, 0.0};
    box.size = {2.0, 2.0, 2.0};
    scene.objects = {ground, box};
    return scene;
}

Inspection inspect(const Scene& scene, const std::string& method, int resolution = 1024) {
    InspectionRequest request;
    request.method = method;
    request.resolution = resolution;
    return inspect_scene(scene, request);
}

glm::ivec2 pixel_of(const Camera& camera, const glm::dvec3& p, int width, int height) {
    const glm::dvec4 clip = camera.projection_matrix() * camera.view_matrix() * glm::dvec4(p, 1.0);
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    return {static_cast<int>((ndc.x * 0.5 + 0.5) * width), static_cast<int>((0.5 - ndc.y * 0.5) * height)};
}

double brightness(const RgbImage& image, glm::ivec2 p, int radius = 3) {
    double sum = 0.0;
    int n = 0;
    for (int y = p.y - radius; y <= p.y + radius; ++y)
        for (int x = p.x - radius; x <= p.x + radius; ++x, ++n) {
            const unsigned char* c = image.at(x, y);
            sum += (c[0] + c[1] + c[2]) / 3.0;
        }
    return sum / n;
}

// The bias the metrics apply at reference pixel i: slope-scaled, from the seen side's normal.
double cpu_bias(const Inspection& in, const ReferenceImage& ref, size_t i) {
    const glm::dvec3& p = ref.position[i];
    const Light& light = in.scene.light;
    const glm::dvec3 along = light.is_directional() ? light.direction : glm::normalize(p - light.position);
    return slope_scaled_bias(in.map(), in.resolution, along, p, ref.facing[i]);
}

}  // namespace

class CameraViewOfEachMethod : public ::testing::TestWithParam<std::string> {};

TEST_P(CameraViewOfEachMethod, GroundUnderTheBoxIsDarkerThanGroundFarFromIt) {
    const Scene scene = floating_box();
    const Inspection in = inspect(scene, GetParam());
    const RgbImage image = render_view(in, ViewKind::camera, {}, kWidth, kHeight);
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

TEST(ShadowMapView, ShowsTheCasterWhereWorldToUvzPutsIt) {
    constexpr int n = 256;
    Scene scene = floating_box();
    scene.objects[0].casts = true;  // the ground is drawn into the map too, farther from the light
    const Inspection in = inspect(scene, "focused", n);
    const RgbImage image = render_view(in, ViewKind::shadow_map, {}, n, n);
    // One screen pixel per texel; texel row v is image row n - 1 - v.
    auto pixel = [&](const glm::dvec3& p) {
        const glm::dvec3 uvz = world_to_uvz(in.map(), p);
        return glm::ivec2(static_cast<int>(uvz.x * n), n - 1 - static_cast<int>(uvz.y * n));
    };
    const glm::ivec2 box = pixel({0.0, 4.0, 0.0});
    const glm::ivec2 ground = pixel({7.0, 0.0, 2.0});
    ASSERT_TRUE(box.x > 8 && box.x < n - 8 && box.y > 8 && box.y < n - 8);
    EXPECT_LT(brightness(image, box, 2) + 30.0, brightness(image, ground, 2))
        << "the box top is nearer the light than the ground: darker";
}

// Issue 5: the GPU pass and the CPU lookup agree on the visible pixels away from shadow edges.
class GpuAgreesWithCpu : public ::testing::TestWithParam<std::string> {};

TEST_P(GpuAgreesWithCpu, OnVisiblePixelsAwayFromShadowEdges) {
    Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/" + GetParam() + ".json");
    scene.camera.aspect = static_cast<double>(kWidth) / kHeight;
    for (const std::string method : {"focused", "lispsm", "xpsm"}) {
        const Inspection in = inspect(scene, method, 1024);
        ViewOptions options;
        options.lit_mask = true;
        const RgbImage gpu = render_view(in, ViewKind::camera, options, kWidth, kHeight);
        const ReferenceImage ref = exact_reference(in.scene, in.triangles, kWidth, kHeight);
        std::vector<int8_t> cpu(ref.visible.size(), -1);
        for (size_t i = 0; i < cpu.size(); ++i)
            if (ref.visible[i]) cpu[i] = in_shadow(in.depth, in.map(), ref.position[i], cpu_bias(in, ref, i)) ? 0 : 1;
        // Away from edges: the 3x3 neighbourhood is visible, of one object, with one CPU verdict.
        size_t compared = 0, agreed = 0;
        for (int y = 1; y < kHeight - 1; ++y)
            for (int x = 1; x < kWidth - 1; ++x) {
                const size_t i = static_cast<size_t>(y) * kWidth + x;
                bool interior = cpu[i] >= 0;
                for (int dy = -1; dy <= 1 && interior; ++dy)
                    for (int dx = -1; dx <= 1 && interior; ++dx) {
                        const size_t j = i + dy * kWidth + dx;
                        interior = cpu[j] == cpu[i] && ref.object[j] == ref.object[i];
                    }
                if (!interior) continue;
                const unsigned char* c = gpu.at(x, y);
                ASSERT_FALSE(c[0] == 255 && c[1] == 0) << "the GPU drew nothing where the reference sees "
                                                       << "object " << ref.object[i] << " at " << x << ", " << y;
                ++compared;
                agreed += (c[0] > 127) == (cpu[i] == 1);
            }
        ASSERT_GT(compared, kWidth * kHeight / 4u);
        EXPECT_GE(static_cast<double>(agreed) / compared, 0.995)
            << method << " on " << GetParam() << ": " << compared - agreed << " of " << compared << " pixels differ";
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, GpuAgreesWithCpu, ::testing::Values("box_on_plane", "default", "spot"));
