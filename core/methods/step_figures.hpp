#pragma once
// The figures the steps draw, as the papers draw them: vectors as labelled arrows, an angle as an
// arc with its value, a length as a labelled dimension, the map's unit cube labelled [0,1]³, the
// light (and, from geometry/preimage.hpp, the volume a projective matrix maps onto a box).
// Only the trace lambdas call these: nothing is drawn without a trace.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <glm/glm.hpp>

#include "geometry/preimage.hpp"
#include "scene/light.hpp"
#include "trace/trace.hpp"

namespace shadowlab {

// A number for a label, to three significant digits: "37.2", "0.0431", "1.2e+05".
inline std::string label_number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", x);
    return text;
}

// A vector from `from` along `direction`, `length` long, its name at its tip: V, L, unitP.
inline Step& draw_arrow(Step& step, const std::string& name, const glm::dvec3& from, const glm::dvec3& direction,
                        double length, Role role) {
    const glm::dvec3 tip = from + length * glm::normalize(direction);
    return step.shape(name, Arrow{from, tip}, role).shape(name + " label", Label{tip, name}, role);
}

// The angle between two directions at `at`, as an arc of `radius` labelled "name = 37.2°".
inline Step& draw_angle(Step& step, const std::string& name, const glm::dvec3& at, const glm::dvec3& from,
                        const glm::dvec3& to, double radius) {
    const double degrees = glm::degrees(std::atan2(glm::length(glm::cross(from, to)), glm::dot(from, to)));
    const glm::dvec3 bisector = glm::normalize(from) + glm::normalize(to);
    const glm::dvec3 label_dir = glm::length(bisector) > 1e-9 ? glm::normalize(bisector) : glm::normalize(from);
    return step.shape(name, AngleArc{at, from, to, radius})
        .shape(name + " label", Label{at + 1.2 * radius * label_dir, name + " = " + label_number(degrees) + "°"});
}

// A length as a dimension line from `from` to `to`, labelled "name = its length" at its middle.
inline Step& draw_dimension(Step& step, const std::string& name, const glm::dvec3& from, const glm::dvec3& to,
                            Role role = Role::step) {
    return step.shape(name, SegmentSet{{{from, to}}}, role)
        .shape(name + " label", Label{0.5 * (from + to), name + " = " + label_number(glm::distance(from, to))}, role);
}

// The map's unit cube (u, v, depth), labelled as the papers label it.
inline Step& draw_unit_cube(Step& step) {
    return step.shape("unit cube", Aabb{glm::dvec3(0.0), glm::dvec3(1.0)}, Role::map)
        .shape("unit cube label", Label{{0.0, 1.0, 0.0}, "[0,1]³"}, Role::map);
}

// The light, in world space, aimed at `aim`: a directional light as the arrow L arriving there
// from `length` away, a spot or point light as its position and the arrow from it toward `aim`.
inline Step& draw_light(Step& step, const Light& light, const glm::dvec3& aim, double length) {
    if (light.is_directional())
        return draw_arrow(step, "L", aim - length * light.direction, light.direction, length, Role::light);
    step.shape("light", PointSet{{light.position}}, Role::light);
    const glm::dvec3 toward = aim - light.position;
    if (!(glm::length(toward) > 0.0)) return step.shape("light label", Label{light.position, "light"}, Role::light);
    return draw_arrow(step, "light", light.position, toward, std::min(length, glm::length(toward)), Role::light);
}

// A frustum's near and far faces, to fill: where a projection's depth starts and ends.
inline PolygonSet near_and_far_faces(const Frustum& f) {
    auto face = [&](int first) {
        std::vector<glm::dvec4> loop;
        for (int i = first; i < first + 4; ++i) loop.emplace_back(f.corners[i], 1.0);
        return loop;
    };
    return PolygonSet{}.add(face(0)).add(face(4));
}

}  // namespace shadowlab
