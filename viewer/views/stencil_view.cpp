// The Stencil count view: per camera pixel, the count the CPU stencil pass leaves
// (core/volumes/stencil_count) under the technique's rule, over the camera image: 0 (lit) grey,
// shaded by how the surface faces the light; 1, 2, ... on a warm ramp; negative counts (z-pass
// from inside a volume) blue. Planar shadows' stencil holds 1 where a flattened caster covers
// the plane.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>

#include <vtkRenderer.h>

#include "views/view_parts.hpp"

namespace shadowlab {
namespace {

Rgb count_colour(int count, int largest, const ReferenceImage& image, size_t i) {
    if (!image.visible[i]) return {20, 20, 24};
    if (count == 0) {
        const auto grey = static_cast<unsigned char>(110.0 + 100.0 * std::max(0.0f, image.facing[i]));
        return {grey, grey, grey};
    }
    if (count < 0) {
        const double t = std::min(1.0, -count / 3.0);
        return {static_cast<unsigned char>(40 * (1 - t)), static_cast<unsigned char>(170 + 60 * t), 255};
    }
    return heat(0.4 + 0.6 * (count - 1) / std::max(1, largest - 1));
}

// The counts under the technique's rule, and where z-pass and z-fail disagree.
struct Counts {
    std::vector<int> count;
    size_t disagree = 0;
};

Counts counts_of(const GeometryResult& t) {
    Counts out;
    if (!t.counts) {
        out.count.assign(t.shadowed.begin(), t.shadowed.end());
        return out;
    }
    out.count = t.rule == StencilRule::zpass ? t.counts->zpass : t.counts->zfail;
    for (size_t i = 0; i < out.count.size(); ++i) out.disagree += t.counts->zpass[i] != t.counts->zfail[i];
    return out;
}

const char* rule_name(StencilRule rule) {
    return rule == StencilRule::zpass ? "z-pass" : rule == StencilRule::zfail ? "z-fail" : "cover";
}

ViewReport build_stencil_view(vtkRenderer* renderer, const Inspection& in, const ViewOptions&) {
    renderer->SetBackground(0.12, 0.13, 0.16);
    if (in.has_map()) {
        add_caption(renderer, in.title() + ": no stencil count (a shadow map; see the Shadow map view)");
        return {};
    }
    const GeometryResult& t = *in.geometry;
    const ReferenceImage& seen = in.reference(in.image_width, in.image_height);  // the image it was judged on
    const Counts c = counts_of(t);
    int largest = 1, shadowed = 0;
    for (size_t i = 0; i < c.count.size(); ++i) {
        largest = std::max(largest, c.count[i]);
        shadowed += seen.visible[i] && c.count[i] != 0;
    }
    RgbImage image(seen.width, seen.height);
    for (size_t i = 0; i < c.count.size(); ++i) {
        const Rgb colour = count_colour(c.count[i], largest, seen, i);
        std::copy(colour.begin(), colour.end(), image.rgb.begin() + 3 * i);
    }
    show_image(renderer, image);
    char caption[320];
    std::snprintf(caption, sizeof caption,
                  "Stencil count — %s, %s (CPU, %dx%d): %d pixels shadowed; z-pass and z-fail differ at %zu pixels\n"
                  "0 grey (lit), 1..%d warm, negative blue (z-pass with the eye inside a volume)",
                  in.name().c_str(), rule_name(t.rule), seen.width, seen.height, shadowed, c.disagree, largest);
    add_caption(renderer, caption);
    return {};
}

}  // namespace

View stencil_view() {
    return {.name = "stencil",
            .title = "Stencil count",
            .prepare = {},  // a technique's own image, traced when it ran
            .build = build_stencil_view,
            .choosers = {},
            .interaction = {.drag = ViewDrag::pans_image}};
}

}  // namespace shadowlab
