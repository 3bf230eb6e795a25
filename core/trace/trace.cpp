#include "trace/trace.hpp"

namespace shadowlab {

const char* to_string(Space space) {
    switch (space) {
        case Space::world: return "world";
        case Space::view: return "view";
        case Space::light: return "light";
        case Space::ppls: return "ppls";
        case Space::unit: return "unit";
    }
    return "?";
}

const char* to_string(Role role) {
    switch (role) {
        case Role::step: return "step";
        case Role::casters: return "casters";
        case Role::receivers: return "receivers";
        case Role::focus: return "focus";
        case Role::light: return "light";
        case Role::view: return "view";
        case Role::map: return "map";
    }
    return "?";
}

}  // namespace shadowlab
