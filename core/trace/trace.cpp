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

}  // namespace shadowlab
