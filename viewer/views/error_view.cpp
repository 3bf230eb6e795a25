// The Error view: the camera image measured against the exact reference. Misclassified pixels are
// painted by kind: false shadow (acne) magenta, false light (leaks) green. For a map the other
// receiver pixels show Lloyd's m, or the factor of it the options choose, as a heat map (log scale,
// 1/8 to 8), judged with the inspection's bias (slope-scaled per pixel unless a constant was
// chosen); a geometric technique has no texels, so its agreeing pixels are light grey where lit and
// dark grey where shadowed.
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

// The per-pixel quantity the heat map shows, its statistics, and its name in the caption (as in
// `measure --json`).
struct Shown {
    const std::vector<float>& image;
    const AliasingStats& stats;
    const char* name;
};

Shown shown(const ShadowError& e, AliasingShown which) {
    switch (which) {
        case AliasingShown::perspective: return {e.m_perspective_image, e.m_perspective, "m_perspective"};
        case AliasingShown::projection: return {e.m_projection_image, e.m_projection, "m_projection"};
        case AliasingShown::total: break;
    }
    return {e.m_image, e.m, "m"};
}

Rgb pixel_colour(const ShadowError& e, const ReferenceImage& ref, const std::vector<float>& heat_image, bool has_map,
                 size_t i) {
    switch (e.verdicts[i]) {
        case PixelVerdict::false_shadow: return {255, 0, 255};
        case PixelVerdict::false_light: return {0, 255, 0};
        case PixelVerdict::agree:
            if (!has_map) return ref.lit[i] ? Rgb{200, 200, 205} : Rgb{110, 110, 118};
            return heat((std::log2(std::max(heat_image[i], 1e-3f)) + 3.0) / 6.0);
        case PixelVerdict::none: break;
    }
    return ref.visible[i] ? Rgb{70, 70, 76} : Rgb{20, 20, 24};
}

RgbImage paint(const ShadowError& e, const ReferenceImage& ref, const std::vector<float>& heat_image, bool has_map) {
    RgbImage image(ref.width, ref.height);
    for (size_t i = 0; i < ref.visible.size(); ++i) {
        const Rgb c = pixel_colour(e, ref, heat_image, has_map, i);
        std::copy(c.begin(), c.end(), image.rgb.begin() + 3 * i);
    }
    return image;
}

std::string shares(const ShadowError& e) {
    char text[160];
    std::snprintf(text, sizeof text, "%.3f%% misclassified (magenta false shadow %.3f%%, green false light %.3f%%)",
                  100 * e.misclassified, 100 * e.false_shadow, 100 * e.false_light);
    return text;
}

}  // namespace

ViewReport build_error_view(vtkRenderer* renderer, const Inspection& in, const ViewOptions& options) {
    renderer->SetBackground(0.12, 0.13, 0.16);
    // A technique is judged on the image it ran on; a map on an image of the panel's size.
    const int width = !in.has_map() ? in.image_width : options.width > 0 ? options.width : 640;
    const int height = !in.has_map()        ? in.image_height
                       : options.height > 0 ? options.height
                                            : std::max(1, static_cast<int>(std::lround(width / in.scene.camera.aspect)));
    const ReferenceImage& ref = in.reference(width, height);
    const ShadowError& e = in.error(width, height);
    const Shown aliasing = shown(e, options.aliasing);
    show_image(renderer, paint(e, ref, aliasing.image, in.has_map()));
    if (!in.has_map()) {
        add_caption(renderer, "Error — " + in.name() + ": " + shares(e) + "; agreeing pixels grey (light: lit)");
        return {};
    }
    char caption[160];
    std::snprintf(caption, sizeof caption, "; %s max %.2f, p95 %.2f (heat: 1/8 to 8)", aliasing.name,
                  aliasing.stats.max, aliasing.stats.p95);
    add_caption(renderer, "Error — " + in.name() + " " + std::to_string(in.resolution) + "²: " + shares(e) + caption);
    return {};
}

}  // namespace shadowlab
