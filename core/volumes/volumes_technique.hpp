#pragma once
// Stencil shadow volumes as a technique: topology, silhouette, extrusion, caps, the infinite
// projection and the per-pixel count, each recorded as a step.
#include "techniques/geometric_technique.hpp"

namespace shadowlab {

// count = zpass | zfail (default zfail).
SettingSpec volumes_count_setting();

GeometryResult compute_volumes(const Scene& scene, const WorldTriangles& triangles, const ReferenceImage& image,
                               const Settings& settings, Trace* trace);

}  // namespace shadowlab
