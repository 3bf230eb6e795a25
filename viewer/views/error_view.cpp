// The Error view: the camera image measured against the exact reference. Receiver pixels show
// Lloyd's m as a heat map (log scale, 1/8 to 8 texel-pixels); misclassified pixels are painted by
// kind: false shadow (acne) magenta, false light (leaks) green. Bias: slope-scaled per pixel, as
// `shadowlab measure` uses by default.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include <vtkRenderer.h>

#include "metrics/shadow_error.hpp"
#include "reference/exact_shadows.hpp"
#include "views/view_parts.hpp"

namespace shadowlab {
namespace {

Rgb pixel_colour(const ShadowError& e, const ReferenceImage& ref, size_t i) {
    switch (e.verdicts[i]) {
        case PixelVerdict::false_shadow: return {255, 0, 255};
        case PixelVerdict::false_light: return {0, 255, 0};
        case PixelVerdict::agree: return heat((std::log2(std::max(e.m_image[i], 1e-3f)) + 3.0) / 6.0);
        case PixelVerdict::none: break;
    }
    return ref.visible[i] ? Rgb{70, 70, 76} : Rgb{20, 20, 24};
}

}  // namespace

ViewReport build_error_view(vtkRenderer* renderer, const Inspection& in, const ViewOptions& options) {
    if (!in.has_map()) {
        renderer->SetBackground(0.12, 0.13, 0.16);
        add_caption(renderer, in.title() + ": no map to measure (a geometric technique; `shadowlab measure` judges it)");
        return {};
    }
    const int width = options.width > 0 ? options.width : 640;
    const int height = options.height > 0 ? options.height : std::max(1, static_cast<int>(std::lround(width / in.scene.camera.aspect)));
    const ReferenceImage ref = exact_reference(in.scene, in.triangles, width, height);
    const ShadowError e = measure_shadow_error(in.scene, ref, in.depth, in.map(), -1.0);
    RgbImage image(width, height);
    for (size_t i = 0; i < ref.visible.size(); ++i) {
        const Rgb c = pixel_colour(e, ref, i);
        std::copy(c.begin(), c.end(), image.rgb.begin() + 3 * i);
    }
    renderer->SetBackground(0.12, 0.13, 0.16);
    show_image(renderer, image);
    char caption[256];
    std::snprintf(caption, sizeof caption,
                  "Error — %s %d²: %.3f%% misclassified (magenta false shadow %.3f%%, green false light %.3f%%); "
                  "m max %.2f, p95 %.2f (heat: m from 1/8 to 8)",
                  in.name().c_str(), in.resolution, 100 * e.misclassified, 100 * e.false_shadow,
                  100 * e.false_light, e.m.max, e.m.p95);
    add_caption(renderer, caption);
    return {};
}

}  // namespace shadowlab
