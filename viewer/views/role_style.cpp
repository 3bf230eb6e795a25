// The one table of what a shape's role looks like in the World, Light space and PPLS views: the
// papers' colours (casters blue, receivers red, the focus region green), the light orange, the map's
// volume cyan, the camera white (a touch of blue: never the grey of anti-aliased text), and the step's own construction
// the highlight yellow.
#include <stdexcept>

#include "render/map_overlay.hpp"
#include "views/space_parts.hpp"

namespace shadowlab {

const glm::dvec3 kSpaceBackground{0.12, 0.13, 0.16};

const RoleStyle& role_style(Role role) {
    static const RoleStyle step{{1.0, 0.9, 0.1}, "this step"}, casters{{0.3, 0.5, 1.0}, "casters"},
        receivers{{1.0, 0.3, 0.3}, "receivers"}, focus{{0.3, 0.9, 0.35}, "focus region"},
        light{{1.0, 0.5, 0.0}, "light"}, view{{0.88, 0.92, 1.0}, "camera"}, map{{0.3, 0.9, 1.0}, "map volume [0,1]³"};
    switch (role) {
        case Role::step: return step;
        case Role::casters: return casters;
        case Role::receivers: return receivers;
        case Role::focus: return focus;
        case Role::light: return light;
        case Role::view: return view;
        case Role::map: return map;
    }
    throw std::logic_error("a role without a style");
}

glm::dvec3 dimmed(const glm::dvec3& colour) { return 0.5 * (colour + kSpaceBackground); }

glm::dvec3 shape_colour(const NamedGeometry& g) {
    return g.map >= 0 ? glm::dvec3(kMapPalette[g.map % kMapPalette.size()]) : role_style(g.role).colour;
}

std::string shape_legend(const NamedGeometry& g, const ShadowSetup& setup) {
    return g.map >= 0 ? map_name(setup, static_cast<size_t>(g.map)) : role_style(g.role).legend;
}

}  // namespace shadowlab
