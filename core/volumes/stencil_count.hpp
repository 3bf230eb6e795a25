#pragma once
// The stencil pass on the CPU: the volume polygons rasterized at the camera's pixel centres, each
// fragment +1 or -1 by which way its face looks at the eye, counted where it lies in front of the
// visible point (z-pass, Heidmann 1991) or behind it out to infinity (z-fail, Carmack's reverse).
// Shadowed where the count is not 0.
#include <vector>

#include "reference/exact_shadows.hpp"
#include "scene/camera.hpp"
#include "techniques/geometry_result.hpp"
#include "volumes/shadow_volume.hpp"

namespace shadowlab {

enum class CountRule { zpass, zfail };

// Both counts for every visible pixel of `image` (whose size gives the pixels), as a GPU's stencil
// pass gets them: each volume polygon rasterized in homogeneous coordinates (raster/polygon_spans.hpp,
// so vertices at infinity, w = 0, need no special case), at pixel centres with the top-left rule
// (adjacent polygons count a shared edge once), its depth interpolated in 1 / w. A face within a
// relative 1e-5 of the visible point's depth counts as behind it (a lit face lies on its own front
// cap). Faces nearer than the near plane are clipped, as on a GPU; the far plane is at infinity.
StencilCounts count_stencil(const ShadowVolume& volume, const Camera& camera, const ReferenceImage& image,
                            CountRule drawn);

}  // namespace shadowlab
