#pragma once
// A geometric technique's part of an Inspection (volumes, planar): its verdicts on the camera
// image, and the polygons a GPU draws into the stencil buffer for it.
#include <optional>
#include <vector>

#include "geometry/homogeneous_clip.hpp"
#include "techniques/technique.hpp"
#include "volumes/stencil_count.hpp"

namespace shadowlab {

// How the stencil polygons mark the shadowed pixels.
enum class StencilRule {
    zpass,  // volume faces in front of the visible point: front +1, back -1 (Heidmann)
    zfail,  // volume faces behind it: back +1, front -1 (Everitt and Kilgard 2002, Carmack's reverse)
    cover   // flattened casters on the receiving plane: 1 where drawn (Blinn, planar projection)
};

struct TechniqueInspection {
    const Technique* technique = nullptr;
    TechniqueResult result;                       // `shadowed` per pixel of `image`
    ReferenceImage image;                         // the camera image's visible points, as judged
    std::vector<HomogeneousPolygon> stencil;      // the polygons, each as often as its multiplicity,
                                                  // counter-clockwise seen from outside; w = 0 at infinity
    StencilRule rule = StencilRule::cover;
    std::optional<StencilCounts> counts;          // volumes: the CPU's count per pixel of `image`
};

// Runs the technique on a width x height camera image of the scene, recording into `trace`.
TechniqueInspection inspect_technique(const Technique& technique, const Scene& scene, const WorldTriangles& triangles,
                                      const Settings& settings, int width, int height, Trace* trace);

}  // namespace shadowlab
