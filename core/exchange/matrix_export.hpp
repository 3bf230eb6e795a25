#pragma once
// A method's maps as shader source or JSON, for pasting into an engine.
#include <string>

#include "methods/map_method.hpp"

namespace shadowlab {

enum class MatrixFormat { glsl, hlsl, json };

// GLSL: `const mat4 worldToUvz0 = mat4(...)`, column by column (GLSL's order), used as M * p.
// HLSL: `static const float4x4 worldToUvz0 = {...}`, row by row, used as mul(M, p).
// Both also give a comment naming the method and how ShadowLab's lookup biases (the depth of the point
// moved `bias` world units toward the light), and each map's z bias scale (XPSM step 18's
// pre-division slope, for engines that bias that way, first order only). JSON: {"method", "maps"}.
std::string export_matrices(const std::string& method, const ShadowSetup& setup, MatrixFormat format);

}  // namespace shadowlab
