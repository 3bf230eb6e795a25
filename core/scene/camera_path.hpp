#pragma once
// A camera moving frame by frame, as a player moves it: sideways (translate), turning on the spot
// about the world's up axis (rotate), or forward along its view (dolly). The shimmer measure
// (metrics/shimmer) follows it.
#include <optional>
#include <string>

#include "scene/camera.hpp"

namespace shadowlab {

struct CameraPath {
    enum class Kind { translate, rotate, dolly };
    Kind kind = Kind::translate;
    int frames = 60;
    // Per frame: world units along the camera's right (translate) or view (dolly) axis, degrees
    // about +y (rotate). 0: automatic, 0.5 % of the distance from the camera to its target per
    // frame, or 0.25° per frame.
    double step = 0.0;
};

const char* to_string(CameraPath::Kind kind);
std::optional<CameraPath::Kind> camera_path_named(const std::string& name);  // nullopt for an unknown name

// The step a path takes per frame for this camera (its own, or the automatic one).
double step_per_frame(const CameraPath& path, const Camera& start);

// The camera at `frame` (0: `start` itself).
Camera camera_at(const Camera& start, const CameraPath& path, int frame);

}  // namespace shadowlab
