#pragma once
// A shadow-map parameterization: a pure function of its inputs and settings that yields one or
// more maps, each taking world points to (u, v, depth) in [0,1]^3, depth growing away from the light.
#include <optional>
#include <string>
#include <vector>
#include <glm/glm.hpp>

#include "methods/settings.hpp"
#include "methods/shadow_inputs.hpp"
#include "trace/trace.hpp"

namespace shadowlab {

struct ShadowMap {
    // World (x, y, z, 1) -> homogeneous (u, v, d, w); u, v, d in [0,1] after division by w.
    glm::dmat4 world_to_uvz{1.0};
    glm::dvec4 viewport{0.0, 0.0, 1.0, 1.0};  // (u0, v0, u1, v1) of the map in the texture
    // Pre-division depth offset per world unit of bias along the light (XPSM step 18):
    // d' = (d_pre - z_bias_scale * bias) / w.
    double z_bias_scale = 1.0;
};

struct ShadowSetup {
    std::vector<ShadowMap> maps;
    std::optional<std::string> fallback;  // the named degradation taken, if any
};

struct Method {
    std::string name;         // as on the command line: "focused"
    std::string title;        // "Focused shadow map"
    std::string description;  // one line
    std::vector<SettingSpec> settings;
    ShadowSetup (*compute)(const ShadowInputs& inputs, const Settings& settings, Trace* trace);
};

// All methods, in the order the UI lists them.
const std::vector<Method>& all_methods();
// Nullptr when no method has that name.
const Method* find_method(const std::string& name);

// (u, v, d) of a world point under a map (after division by w).
inline glm::dvec3 world_to_uvz(const ShadowMap& map, const glm::dvec3& p) {
    const glm::dvec4 h = map.world_to_uvz * glm::dvec4(p, 1.0);
    return glm::dvec3(h) / h.w;
}

}  // namespace shadowlab
