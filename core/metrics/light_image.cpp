#include "metrics/light_image.hpp"

#include <cmath>

#include "methods/light_fit.hpp"

namespace shadowlab {
namespace {

// A cube face's axis (0: x, 1: y, 2: z) and the way it faces along it (+1, -1).
int face_axis_of(int face) { return face / 2; }
double face_sign_of(int face) { return face % 2 == 0 ? 1.0 : -1.0; }

}  // namespace

LightImage::LightImage(const Light& light) : light_(light) {
    if (light.is_directional())
        light_from_world_ = light_basis(light.direction, stable_up_hint(light.direction)).light_from_world;
}

LightImagePoint LightImage::of(const glm::dvec3& p) const {
    if (light_.is_directional()) return {.chart = 0, .at = glm::dvec2(light_from_world_ * glm::dvec4(p, 1.0))};
    const glm::dvec3 d = p - light_.position;
    const glm::dvec3 size = glm::abs(d);
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
    const int face = 2 * axis + (d[axis] < 0.0 ? 1 : 0);
    return {.chart = face, .at = *on(face, p)};
}

std::optional<glm::dvec2> LightImage::on(int chart, const glm::dvec3& p) const {
    if (light_.is_directional()) return glm::dvec2(light_from_world_ * glm::dvec4(p, 1.0));
    const glm::dvec3 d = p - light_.position;
    const int axis = face_axis_of(chart);
    const double along = face_sign_of(chart) * d[axis];
    if (!(along > 0.0)) return std::nullopt;
    return glm::dvec2(d[(axis + 1) % 3], d[(axis + 2) % 3]) / along;
}

}  // namespace shadowlab
