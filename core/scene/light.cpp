#include "scene/light.hpp"

namespace shadowlab {

const char* to_string(LightType type) {
    switch (type) {
        case LightType::directional: return "directional";
        case LightType::spot: return "spot";
        case LightType::point: return "point";
    }
    return "unknown";
}

}  // namespace shadowlab
