#pragma once
// Scenes and pixel checks shared by the viewer's tests.
#include <cstdint>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>
#include <glm/glm.hpp>

#include "metrics/shadow_error.hpp"
#include "model/inspection.hpp"
#include "reference/exact_shadows.hpp"
#include "render/rgb_image.hpp"
#include "scene/scene.hpp"
#include "scene/scene_loader.hpp"
#include "views/offscreen_view.hpp"

namespace shadowlab::testing {

// A box floating over a ground plane under an almost overhead sun; the camera looks at the ground
// beneath the box from the side, so the shadow is in view and not hidden by the box.
inline Scene floating_box(int width, int height) {
    Scene scene;
    scene.name = "floating box";
    scene.camera.position = {0.0, 6.0, 12.0};
    scene.camera.target = {0.0, 0.0, 0.0};
    scene.camera.aspect = static_cast<double>(width) / height;
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

inline glm::ivec2 pixel_of(const Camera& camera, const glm::dvec3& p, int width, int height) {
    const glm::dvec4 clip = camera.projection_matrix() * camera.view_matrix() * glm::dvec4(p, 1.0);
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    return {static_cast<int>((ndc.x * 0.5 + 0.5) * width), static_cast<int>((0.5 - ndc.y * 0.5) * height)};
}

inline double brightness(const RgbImage& image, glm::ivec2 p, int radius = 3) {
    double sum = 0.0;
    int n = 0;
    for (int y = p.y - radius; y <= p.y + radius; ++y)
        for (int x = p.x - radius; x <= p.x + radius; ++x, ++n) {
            const unsigned char* c = image.at(x, y);
            sum += (c[0] + c[1] + c[2]) / 3.0;
        }
    return sum / n;
}

struct Agreement {
    size_t compared = 0, agreed = 0;
    size_t undrawn = 0;  // compared pixels the GPU left red (the lit mask's background): nothing drawn
    double share() const { return compared ? static_cast<double>(agreed) / compared : 0.0; }
};

// A GPU lit mask (white lit, black shadowed, red nothing) against CPU verdicts per pixel (1 lit,
// 0 shadowed, -1 nothing visible), on the pixels away from shadow edges: the 3x3 neighbourhood
// visible, of one object, with one CPU verdict.
inline Agreement agreement(const RgbImage& gpu, const std::vector<int8_t>& cpu, const ReferenceImage& ref) {
    Agreement a;
    const int width = gpu.width, height = gpu.height;
    for (int y = 1; y < height - 1; ++y)
        for (int x = 1; x < width - 1; ++x) {
            const size_t i = static_cast<size_t>(y) * width + x;
            bool interior = cpu[i] >= 0;
            for (int dy = -1; dy <= 1 && interior; ++dy)
                for (int dx = -1; dx <= 1 && interior; ++dx) {
                    const size_t j = i + dy * width + dx;
                    interior = cpu[j] == cpu[i] && ref.object[j] == ref.object[i];
                }
            if (!interior) continue;
            const unsigned char* c = gpu.at(x, y);
            a.undrawn += c[0] == 255 && c[1] == 0;
            ++a.compared;
            a.agreed += (c[0] > 127) == (cpu[i] == 1);
        }
    return a;
}

// A shipped scene (data/scenes/NAME.json) whose camera's aspect is the image's, width x height.
inline Scene shipped_scene(const std::string& name, int width, int height) {
    Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/" + name + ".json");
    scene.camera.aspect = static_cast<double>(width) / height;
    return scene;
}

inline Inspection inspect(const Scene& scene, const std::string& method, int resolution) {
    InspectionRequest request;
    request.method = method;
    request.resolution = resolution;
    return inspect_scene(scene, request);
}

// The GPU pass's lit mask of a map method against the CPU lookup (ShadowReader, the inspection's
// filter and bias, shadowed below one half) on a width x height image of the inspection's camera.
inline Agreement gpu_against_cpu_lookup(const Inspection& in, int width, int height) {
    ViewOptions options;
    options.lit_mask = true;
    const RgbImage gpu = render_view(in, view_or_throw("camera"), options, width, height);
    const ReferenceImage& ref = in.reference(width, height);
    const ShadowReader reader(in.setup, in.depth(), in.scene.light, in.lookup);
    std::vector<int8_t> cpu(ref.visible.size(), -1);
    for (size_t i = 0; i < cpu.size(); ++i)
        if (ref.visible[i])
            cpu[i] = reader.visibility({.position = ref.position[i], .normal = ref.normal[i]}) < 0.5 ? 0 : 1;
    return agreement(gpu, cpu, ref);
}

// What a command prints on stdout while it runs.
template <class Run>
std::string printed(Run&& run) {
    std::ostringstream out;
    std::streambuf* saved = std::cout.rdbuf(out.rdbuf());
    try {
        run();
    } catch (...) {
        std::cout.rdbuf(saved);
        throw;
    }
    std::cout.rdbuf(saved);
    return out.str();
}

}  // namespace shadowlab::testing
