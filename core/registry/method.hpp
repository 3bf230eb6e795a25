#pragma once
// The one list of everything `--method` names: the shadow-map methods and the geometric techniques,
// each entry complete (settings, the lights it handles, what it produces, its compute function), so
// that the CLI, the window, the tests and the benchmarks iterate it and none names a method in code.
#include <deque>
#include <string>
#include <vector>

#include "maps/shadow_map.hpp"
#include "methods/settings.hpp"
#include "methods/shadow_inputs.hpp"
#include "reference/exact_shadows.hpp"
#include "scene/tessellation.hpp"
#include "techniques/geometry_result.hpp"
#include "trace/trace.hpp"

namespace shadowlab {

// The lights a method handles itself; for the others it takes a named fallback.
struct LightSupport {
    bool directional = true, spot = true, point = true;

    bool handles(LightType type) const;
    std::string text() const;  // "directional, spot, point"
};

// What a map method's maps are promised to cover (u, v, d in [0,1]).
enum class Coverage {
    visible_receivers,  // every receiver point the camera sees (uniform, focused)
    shadowable_points,  // the visible points a caster can shadow: a warp spends no texel elsewhere
    seen_points,        // the receiver points of the camera's depth image only (virtual: their pages)
};

enum class Produces {
    maps,     // a ShadowSetup: maps, their tiles, the selection rule
    geometry  // a GeometryResult: stencil polygons and per-pixel verdicts
};
const char* to_string(Produces produces);

// A shadow-map method: a pure function of its inputs and settings.
using ComputeMaps = ShadowSetup (*)(const ShadowInputs& inputs, const Settings& settings, Trace* trace);
// A geometric technique, judged on the camera image `image` (its visible points: position, visible,
// object; its lit and facing fields are not read).
using ComputeGeometry = GeometryResult (*)(const Scene& scene, const WorldTriangles& triangles,
                                           const ReferenceImage& image, const Settings& settings, Trace* trace);

// Whether a map method's settings read ShadowInputs::visible_depths (the camera's depth image).
using ReadsVisibleDepths = bool (*)(const Settings& settings);

// How a map method whose texel size is a setting rather than the texture's resolution makes its
// texels `factor` times finer (virtual: a lower resolution bias); nullopt when it cannot. Methods
// without one get finer texels from a higher resolution.
using FinerTexels = std::optional<SettingsChange> (*)(const Settings& settings, double factor);

struct Method {
    std::string name;         // as on the command line: "focused"
    std::string title;        // "Focused shadow map"
    std::string description;  // one line
    std::vector<SettingSpec> settings;
    LightSupport lights;
    Coverage covers = Coverage::visible_receivers;      // map methods
    ComputeMaps compute_maps = nullptr;                 // a shadow-map method, or
    ComputeGeometry compute_geometry = nullptr;         // a geometric technique: exactly one is set
    ReadsVisibleDepths reads_visible_depths = nullptr;  // a map method that may: when its settings say so
    FinerTexels finer_texels = nullptr;                 // a map method whose texel size is a setting

    Produces produces() const { return compute_maps ? Produces::maps : Produces::geometry; }
    bool makes_maps() const { return produces() == Produces::maps; }
    // The caller measures the visible depths (a trace of the camera's view) for these settings only.
    bool wants_visible_depths(const Settings& s) const { return reads_visible_depths && reads_visible_depths(s); }
};

// Every method, in the order the UI lists them: the shipped maps, the shipped geometric techniques,
// then any registered later. A deque: registering one more never moves the others, so pointers to
// entries stay valid.
const std::deque<Method>& all_methods();
// Nullptr when no method has that name.
const Method* find_method(const std::string& name);
// The method, or std::invalid_argument "unknown method 'x' (known: a, b, ...)".
const Method& method_or_throw(const std::string& name);
// Every name, joined by `separator`: for help texts.
std::string method_names(const std::string& separator = " | ");

// Adds a method after the others (a test's throw-away method, a plug-in). Throws
// std::invalid_argument when the name is taken or not exactly one compute function is set.
void register_method(Method method);

}  // namespace shadowlab
