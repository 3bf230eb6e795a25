#pragma once
#include <array>

#include "methods/map_method.hpp"

namespace shadowlab {

// Tetrahedron shadow maps (Liao, "Shadow mapping for omnidirectional light using tetrahedron
// mapping", GPU Pro 2010; bgfx example 16): four wide perspective maps from a spot or point light,
// one through each face of a regular tetrahedron about it, packed in one square texture cut by its
// diagonals, each face drawn inside its own triangle (its mask); a point reads the face whose axis is
// nearest its direction from the light. A directional light takes the focused map as a named fallback.
ShadowSetup compute_tetra(const ShadowInputs& inputs, const Settings& settings, Trace* trace);
std::vector<SettingSpec> tetra_settings();

// The four faces' axes (unit directions from the light to the faces' centres), in the order of the
// setup's maps: -z below the light's level, -x above, +x above, +z below (two faces below looking
// along -z and +z, two above along -x and +x, as bgfx and Liao turn the tetrahedron).
std::array<glm::dvec3, 4> tetra_face_axes();

}  // namespace shadowlab
