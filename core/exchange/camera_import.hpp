#pragma once
// An engine's camera, read as the engine writes it: its view matrix (world -> eye) and its
// projection (eye -> clip), turned into the scene's Camera. The light's matrices are read the same
// way (io/matrix_import.hpp, io/matrix_text.hpp), and one file may hold both.
//
// The file:
//   JSON   {"camera": {"view": V, "projection": P},
//           "matrices": [...], ...}          the light's keys may stand beside (io/matrix_import.hpp)
//          V and P as the light's matrices: 4 rows of 4, or 16 numbers with their storage named.
//   GLSL   uniform mat4 view = mat4(...);        mat4 projection = mat4(...);       (by columns)
//   HLSL   float4x4 view = {...};                float4x4 projection = {...};       (by rows)
//          the view is the one matrix whose name holds "view" but not "proj" (view, viewMatrix, u_View),
//          the projection the one whose name holds "proj" but not "view" (projection, uProj); others
//          (a light's viewProjection) are passed over.
// World coordinates are the scene's. The conventions (CameraConventions) are the light's storage,
// clip depth and reversed Z, and two of the camera's own: which way clip y runs (Vulkan's down the
// image) and which way the eye looks (OpenGL's right-handed -z, Direct3D's left-handed +z).
//
// The camera must be a pinhole or an orthographic one: a rigid view (rotation and translation), a
// symmetric perspective projection with a finite far plane or a centred orthographic one (its last row
// (0, 0, 0, 1)). Anything else is refused with std::invalid_argument, one line naming the file, the
// matrix and what is wrong (a singular matrix, a skewed or scaled view, an off-centre or oblique
// projection, an infinite far plane, a convention that does not fit).
#include <map>
#include <string>
#include <vector>
#include <glm/glm.hpp>

#include "geometry/aabb.hpp"
#include "io/matrix_text.hpp"
#include "maps/clip_conventions.hpp"
#include "methods/settings.hpp"
#include "scene/camera.hpp"

namespace shadowlab {

enum class ClipY {
    up,    // clip y runs up the image: OpenGL, Direct3D
    down,  // clip y runs down the image: Vulkan (its projection's y row negated)
};

enum class EyeForward {
    minus_z,  // right-handed eye space looking down -z: OpenGL, Vulkan, glm::lookAt and glm::perspective
    plus_z,   // left-handed eye space looking down +z: Direct3D's XMMatrixLookAtLH and XMMatrixPerspectiveFovLH
};

struct CameraConventions {
    MatrixStorage storage = MatrixStorage::automatic;
    ClipDepth depth = ClipDepth::minus_one_to_one;
    bool reversed_z = false;
    ClipY y = ClipY::up;
    EyeForward looks_along = EyeForward::minus_z;
};

// The conventions as settings, named as the custom method's (storage, clip_depth, reversed_z) and
// clip_y (up | down), looks_along (minus_z | plus_z); and read from key=value overrides, throwing
// std::invalid_argument for an unknown key or word.
std::vector<SettingSpec> camera_convention_settings();
CameraConventions camera_conventions_from(const std::map<std::string, std::string>& overrides);

// The two matrices as the file gives them, applied as M p, and the fields they were read from.
struct EngineCamera {
    glm::dmat4 eye_from_world;
    glm::dmat4 clip_from_eye;
    std::string view_field;        // "camera.view", or the shader's name: "viewMatrix, matrix 0 (line 3)"
    std::string projection_field;  // "camera.projection", or "projection, matrix 1 (line 4)"
};

EngineCamera parse_engine_camera(const std::string& text, MatrixStorage storage, const std::string& file);

// The camera the matrices describe, under `conventions`. Its target, about which the window
// orbits and of which the matrices give only the direction, lies ahead at the distance of the
// scene's centre (as a glTF camera's: scene/gltf_scene.cpp).
Camera camera_from_engine(const EngineCamera& engine, const CameraConventions& conventions, const Aabb& scene_bounds,
                          const std::string& file);

// The camera of an engine's file, to replace the scene's: scene.camera = import_camera(...).
Camera import_camera(const std::string& file, const CameraConventions& conventions, const Aabb& scene_bounds);

}  // namespace shadowlab
