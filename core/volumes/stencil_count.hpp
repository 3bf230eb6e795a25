#pragma once
// The stencil pass on the CPU: along each pixel's eye ray, the volume faces crossed, +1 or -1 by
// which way each faces the eye, counted in front of the visible point (z-pass, Heidmann) or behind
// it out to infinity (z-fail, Carmack's reverse). Shadowed where the count is not 0.
#include <vector>

#include "reference/exact_shadows.hpp"
#include "scene/camera.hpp"
#include "volumes/shadow_volume.hpp"

namespace shadowlab {

enum class CountRule { zpass, zfail };

struct StencilCounts {
    // Per pixel, row-major like the image. Where nothing is visible the counts are 0.
    std::vector<int> zpass;      // front-facing faces in front of the visible point, minus back-facing ones
    std::vector<int> zfail;      // back-facing faces behind it (to infinity), minus front-facing ones
    std::vector<int> fragments;  // faces the rule draws that the near plane leaves: quads, and caps for z-fail
};

// Both counts for every visible pixel of `image` (whose size gives the rays), each volume polygon
// tested exactly against each eye ray it may cover: the edge planes through the eye and the
// polygon's plane, in homogeneous form, so that vertices at infinity (w = 0) need no special case.
// A face within a relative 1e-5 of the visible point's depth counts as behind it (a lit face lies
// on its own front cap). Faces nearer than the near plane are clipped, as on a GPU.
StencilCounts count_stencil(const ShadowVolume& volume, const Camera& camera, const ReferenceImage& image,
                            CountRule drawn);

}  // namespace shadowlab
