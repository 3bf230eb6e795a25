#pragma once
// The GPU's visibility against the CPU lookup's on the same pixels (under Xvfb): the Camera view
// drawn with its pass's visibility output, and |GPU − CPU| over the pixels that see one face of one
// object, and over the CPU's penumbrae alone (most pixels are fully lit or fully shadowed, so that a
// GPU filtering nothing would still differ little on average).
#include <cmath>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include "lookup/kernel_taps.hpp"
#include "lookup/shadow_reader.hpp"
#include "render/shadow_map_pass.hpp"
#include "render/x_display.hpp"
#include "view_test_support.hpp"
#include "views/view.hpp"

namespace shadowlab::testing {

// The Camera view drawn as render_view draws it, its pass switched to the visibility output.
inline RgbImage gpu_visibility(const Inspection& in, int width, int height) {
    const XDisplay x("the visibility parity test");
    vtkNew<vtkRenderWindow> window;
    window->SetInteractor(nullptr);
    window->SetDisplayId(x.handle());
    window->SetOffScreenRendering(1);
    window->SetMultiSamples(0);
    window->SetSize(width, height);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    build_view(renderer, in, view_or_throw("camera"), ViewOptions{.lit_mask = true, .width = width, .height = height});
    ShadowMapPass::SafeDownCast(renderer->GetPass())->SetOutput(ShadowMapPass::Output::visibility);
    window->Render();
    RgbImage image = grab(window);
    window->Finalize();
    return image;
}

// A pixel whose 3x3 neighbourhood sees one face of one object: no object edge or box corner inside.
inline bool inside_one_face(const ReferenceImage& ref, int x, int y) {
    const size_t i = static_cast<size_t>(y) * ref.width + x;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const size_t j = i + dy * ref.width + dx;
            if (!ref.visible[j] || ref.object[j] != ref.object[i] || ref.normal[j] != ref.normal[i]) return false;
        }
    return true;
}

struct VisibilityParity {
    size_t compared = 0;
    size_t penumbra = 0;  // pixels the CPU sees partly lit (visibility in (0.05, 0.95))
    size_t shadowed = 0;  // pixels the CPU sees less than half lit
    size_t shaded = 0;    // pixels the CPU sees less than fully lit (below 0.95)
    double mean_difference = 0.0, penumbra_mean_difference = 0.0;
};

// `ref`: the exact reference at the image's size (its points are the pixels compared).
inline VisibilityParity gpu_against_cpu_visibility(const Inspection& in, const ReferenceImage& ref) {
    const RgbImage gpu = gpu_visibility(in, ref.width, ref.height);
    const ShadowReader reader(in.setup, in.depth(), in.scene.light, in.lookup);
    VisibilityParity parity;
    double sum = 0.0, penumbra_sum = 0.0;
    for (int y = 1; y < ref.height - 1; ++y)
        for (int x = 1; x < ref.width - 1; ++x) {
            if (!inside_one_face(ref, x, y)) continue;
            const size_t i = static_cast<size_t>(y) * ref.width + x;
            const double cpu = reader.visibility(
                {.position = ref.position[i], .normal = ref.normal[i], .rotation = pixel_rotation(x, y)});
            const double difference = std::abs(gpu.at(x, y)[0] / 255.0 - cpu);
            const bool penumbra = cpu > 0.05 && cpu < 0.95;
            sum += difference;
            penumbra_sum += penumbra ? difference : 0.0;
            ++parity.compared;
            parity.penumbra += penumbra;
            parity.shadowed += cpu < 0.5;
            parity.shaded += cpu < 0.95;
        }
    parity.mean_difference = parity.compared ? sum / parity.compared : 0.0;
    parity.penumbra_mean_difference = parity.penumbra ? penumbra_sum / parity.penumbra : 0.0;
    return parity;
}

}  // namespace shadowlab::testing
