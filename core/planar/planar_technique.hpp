#pragma once
// Planar projection shadows as a technique: per receiving plane, the plane, the light, the matrix,
// the flattened casters, and the pixels they cover.
#include "techniques/geometric_technique.hpp"

namespace shadowlab {

GeometryResult compute_planar(const Scene& scene, const WorldTriangles& triangles, const ReferenceImage& image,
                              const Settings& settings, Trace* trace);

}  // namespace shadowlab
