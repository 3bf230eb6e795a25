#include "methods/omni_light.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "methods/focused.hpp"
#include "methods/map_fit.hpp"
#include "methods/step_figures.hpp"
#include "methods/warp_common.hpp"

namespace shadowlab {
namespace {

double distance_to_box(const glm::dvec3& p, const Aabb& box) {
    return glm::length(p - glm::clamp(p, box.min, box.max));
}

// A circle of `radius` about `centre` in the plane spanned by a and b.
std::vector<glm::dvec4> circle(const glm::dvec3& centre, double radius, const glm::dvec3& a, const glm::dvec3& b) {
    std::vector<glm::dvec4> points;
    for (int k = 0; k < 64; ++k) {
        const double t = 2 * std::numbers::pi * k / 64;
        points.emplace_back(centre + radius * (std::cos(t) * a + std::sin(t) * b), 1.0);
    }
    return points;
}

}  // namespace

LightRange omni_range(const ShadowInputs& in) {
    if (in.light.range) return *in.light.range;
    const glm::dvec3 light = in.light.position;
    double far = 0.0;
    for (const glm::dvec3& corner : in.scene_bounds.corners()) far = std::max(far, glm::length(corner - light));
    far *= 1.01;
    double nearest = far;
    for (const Aabb& caster : in.casters) nearest = std::min(nearest, distance_to_box(light, caster));
    return {.near = std::max(0.99 * nearest, far * 1e-4), .far = far};
}

bool omni_or_focused(const std::string& method, const ShadowInputs& in, const Settings& settings, ShadowSetup& setup,
                     Trace* trace) {
    if (!in.light.is_directional()) return true;
    if (const auto body = body_or_uniform(in, settings, setup, trace))
        fall_back_to_focused(Note{NoteKind::directional_light, method + " looks out from a light's position; the "
                                                                        "focused map for this directional light"},
                             in, *body, setup, trace);
    return false;
}

void record_range(Trace& t, const Light& light, const LightRange& range, bool from_scene) {
    Step& step = t.add("range", "The light's range",
                       from_scene ? "near: just short of the nearest caster; far: beyond the scene's farthest corner"
                                  : "the scene's light.range: nothing nearer casts, nothing farther is lit",
                       Space::world)
                     .value("near", range.near)
                     .value("far", range.far);
    draw_light(step, light, light.position, 0.0);
    const glm::dvec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    for (const auto& [name, radius] : {std::pair{"near", range.near}, std::pair{"far", range.far}}) {
        const Role role = std::string(name) == "near" ? Role::light : Role::map;
        step.shape(std::string(name) + " xz", PolygonSet{}.add(circle(light.position, radius, x, z)), role)
            .shape(std::string(name) + " xy", PolygonSet{}.add(circle(light.position, radius, x, y)), role)
            .shape(std::string(name) + " label",
                   Label{light.position + radius * x, std::string(name) + " = " + label_number(radius)}, role);
    }
}

}  // namespace shadowlab
