#pragma once
// The GLSL of the projection kinds, written from their descriptors (maps/projection_kind.hpp): each
// registered kind's render/glsl/<glsl>.glsl once, then the functions the other shaders call, each
// choosing the map's kind by shadowMapProjection[i]. A kind's file defines <glsl_prefix>Homogeneous,
// UvDerivative, DepthSlope, DistanceBackToDepth and, if the kind has a clip distance, ClipDistance.
#include <string>

namespace shadowlab {

// After map_projection.glsl, in both stages.
std::string projection_glsl();

}  // namespace shadowlab
