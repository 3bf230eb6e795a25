#include "scene/camera_path.hpp"

#include <array>
#include <cmath>
#include <utility>
#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab {
namespace {

constexpr double kAutomaticShare = 0.005;   // of the camera's distance to its target, per frame
constexpr double kAutomaticDegrees = 0.25;  // per frame

constexpr std::array<std::pair<CameraPath::Kind, const char*>, 3> kNames{{{CameraPath::Kind::translate, "translate"},
                                                                          {CameraPath::Kind::rotate, "rotate"},
                                                                          {CameraPath::Kind::dolly, "dolly"}}};

// The camera's right axis, perpendicular to its view and its up.
glm::dvec3 right_of(const Camera& c) { return glm::normalize(glm::cross(c.view_direction(), c.up)); }

}  // namespace

const char* to_string(CameraPath::Kind kind) {
    for (const auto& [k, name] : kNames)
        if (k == kind) return name;
    return "?";
}

std::optional<CameraPath::Kind> camera_path_named(const std::string& name) {
    for (const auto& [k, n] : kNames)
        if (name == n) return k;
    return std::nullopt;
}

double step_per_frame(const CameraPath& path, const Camera& start) {
    if (path.step != 0.0) return path.step;
    return path.kind == CameraPath::Kind::rotate ? kAutomaticDegrees
                                                 : kAutomaticShare * glm::length(start.target - start.position);
}

Camera camera_at(const Camera& start, const CameraPath& path, int frame) {
    const double amount = frame * step_per_frame(path, start);
    Camera c = start;
    switch (path.kind) {
        case CameraPath::Kind::translate: {
            const glm::dvec3 offset = amount * right_of(start);
            c.position += offset, c.target += offset;
            break;
        }
        case CameraPath::Kind::dolly: {
            const glm::dvec3 offset = amount * start.view_direction();
            c.position += offset, c.target += offset;
            break;
        }
        case CameraPath::Kind::rotate: {
            // The target turns about the world's up axis through the camera: the camera turns on the spot.
            const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), glm::radians(amount), glm::dvec3(0.0, 1.0, 0.0));
            c.target = start.position + glm::dvec3(turn * glm::dvec4(start.target - start.position, 0.0));
            c.up = glm::dvec3(turn * glm::dvec4(start.up, 0.0));
            break;
        }
    }
    return c;
}

}  // namespace shadowlab
