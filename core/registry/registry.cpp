// The list of methods: one line each. Adding a method: its files, one line here (see
// docs/ARCHITECTURE.md, "Adding a method").
#include <algorithm>
#include <stdexcept>

#include "lookup/lookup_settings.hpp"
#include "methods/cascades.hpp"
#include "methods/cube.hpp"
#include "methods/custom.hpp"
#include "methods/dpsm.hpp"
#include "methods/focused.hpp"
#include "methods/lispsm.hpp"
#include "methods/logpsm.hpp"
#include "methods/psm.hpp"
#include "methods/tetra.hpp"
#include "methods/tsm.hpp"
#include "methods/uniform.hpp"
#include "methods/virtual_map.hpp"
#include "methods/xpsm.hpp"
#include "planar/planar_technique.hpp"
#include "registry/filter_registry.hpp"
#include "registry/method.hpp"
#include "volumes/volumes_technique.hpp"

namespace shadowlab {
namespace {

constexpr LightSupport kAllLights{};
constexpr LightSupport kDirectionalOnly{true, false, false};
constexpr LightSupport kPositionedOnly{false, true, true};

// Every map is read through a filter and a bias: their settings follow a map method's own, except
// those it declares itself (with a default of its own).
// Again after a filter is registered: its settings are added, and the filter setting (the method's
// own default kept) offers it.
void add_lookup_settings(Method& method) {
    if (!method.makes_maps()) return;
    for (const SettingSpec& spec : lookup_settings()) {
        const auto own = std::find_if(method.settings.begin(), method.settings.end(),
                                      [&](const SettingSpec& s) { return s.name == spec.name; });
        if (own == method.settings.end())
            method.settings.push_back(spec);
        else if (spec.name == "filter")
            own->choices = spec.choices, own->description = spec.description;
    }
}

std::deque<Method> with_lookup_settings(std::deque<Method> methods) {
    for (Method& m : methods) add_lookup_settings(m);
    return methods;
}

std::deque<Method>& registry() {
    static std::deque<Method> methods = with_lookup_settings({
        {.name = "uniform",
         .title = "Uniform shadow map",
         .description = "orthographic map fit to the whole scene's bounds",
         .lights = kAllLights,
         .compute_maps = compute_uniform},
        {.name = "focused",
         .title = "Focused shadow map",
         .description = "orthographic map fit to the intersection body",
         .settings = {body_kernel_setting()},
         .lights = kAllLights,
         .compute_maps = compute_focused},
        {.name = "psm",
         .title = "Perspective shadow map",
         .description = "Stamminger and Drettakis: the map built in the camera's post-perspective space",
         .settings = psm_settings(),
         .lights = kAllLights,
         .covers = Coverage::shadowable_points,
         .compute_maps = compute_psm},
        {.name = "lispsm",
         .title = "Light space perspective shadow map",
         .description = "Wimmer et al.: a perspective warp along the view, in light space",
         .settings = lispsm_settings(),
         .lights = LightSupport{.directional = true, .spot = true, .point = false},
         .covers = Coverage::shadowable_points,
         .compute_maps = compute_lispsm,
         .reads_visible_depths = lispsm_reads_visible_depths},
        {.name = "logpsm",
         .title = "Logarithmic perspective shadow map",
         .description = "Lloyd et al.: LiSPSM's perspective warp, then a logarithm along the view; curved edges split",
         .settings = logpsm_settings(),
         .lights = kDirectionalOnly,
         .covers = Coverage::shadowable_points,
         .compute_maps = compute_logpsm},
        {.name = "tsm",
         .title = "Trapezoidal shadow map",
         .description = "Martin and Tan: the view, seen from the light, bounded by a trapezoid warped onto the map",
         .settings = tsm_settings(),
         .lights = kDirectionalOnly,
         .covers = Coverage::shadowable_points,
         .compute_maps = compute_tsm},
        {.name = "xpsm",
         .title = "Extended perspective shadow map",
         .description = "Gusev's XPSM: a projection vector in light space, w clipped at εW",
         .settings = xpsm_settings(),
         .lights = kDirectionalOnly,
         .covers = Coverage::shadowable_points,
         .compute_maps = compute_xpsm},
        {.name = "cascades",
         .title = "Cascaded shadow maps",
         .description = "Engel; Zhang et al.: the view split by depth, one map per split in an atlas",
         .settings = cascades_settings(),
         .lights = kDirectionalOnly,
         .compute_maps = compute_cascades,
         .reads_visible_depths = cascades_read_visible_depths},
        {.name = "virtual",
         .title = "Virtual shadow map",
         .description = "UE5's sun shadows: clipmap levels about the camera in pages, only the pages the view's "
                        "depth image needs drawn, within a budget",
         .settings = virtual_settings(),
         .lights = kDirectionalOnly,
         .covers = Coverage::seen_points,
         .compute_maps = compute_virtual,
         .reads_visible_depths = virtual_reads_visible_depths,
         .finer_texels = virtual_finer_texels},
        {.name = "dpsm",
         .title = "Dual-paraboloid shadow map",
         .description = "Brabec et al.: two hemispheres around the light, each a paraboloid onto a disc",
         .settings = dpsm_settings(),
         .lights = kPositionedOnly,
         .compute_maps = compute_dpsm},
        {.name = "cube",
         .title = "Cube shadow map",
         .description = "six 90° perspective faces around the light, chosen by the major axis",
         .settings = cube_settings(),
         .lights = kPositionedOnly,
         .compute_maps = compute_cube},
        {.name = "tetra",
         .title = "Tetrahedron shadow map",
         .description = "Liao, bgfx: four perspective faces of a tetrahedron around the light in one texture, each "
                        "in its triangle, chosen by the nearest face axis",
         .settings = tetra_settings(),
         .lights = kPositionedOnly,
         .compute_maps = compute_tetra},
        {.name = "custom",
         .title = "Your engine's matrices",
         .description = "an engine's light view-projections, read from a GLSL, HLSL or JSON file under its named "
                        "conventions, with a coverage report",
         .settings = custom_settings(),
         .lights = kAllLights,
         .compute_maps = compute_custom},
        {.name = "volumes",
         .title = "Stencil shadow volumes",
         .description = "Crow, Heidmann, Everitt and Kilgard: silhouette edges extruded to infinity, faces counted "
                        "per eye ray",
         .settings = {volumes_count_setting()},
         .lights = kAllLights,
         .compute_geometry = compute_volumes},
        {.name = "planar",
         .title = "Planar projection shadows",
         .description = "Blinn: the casters flattened onto each receiving plane by the matrix (P . L) I - L P^T",
         .lights = kAllLights,
         .compute_geometry = compute_planar},
    });
    return methods;
}

}  // namespace

bool LightSupport::handles(LightType type) const {
    switch (type) {
        case LightType::directional: return directional;
        case LightType::spot: return spot;
        case LightType::point: return point;
    }
    return false;
}

std::string LightSupport::text() const {
    std::string out;
    for (LightType type : {LightType::directional, LightType::spot, LightType::point})
        if (handles(type)) out += (out.empty() ? "" : ", ") + std::string(to_string(type));
    return out;
}

const char* to_string(Produces produces) { return produces == Produces::maps ? "shadow maps" : "stencil geometry"; }

const std::deque<Method>& all_methods() { return registry(); }

const Method* find_method(const std::string& name) {
    for (const Method& m : registry())
        if (m.name == name) return &m;
    return nullptr;
}

std::string method_names(const std::string& separator) {
    std::string names;
    for (const Method& m : registry()) names += (names.empty() ? "" : separator) + m.name;
    return names;
}

const Method& method_or_throw(const std::string& name) {
    if (const Method* m = find_method(name)) return *m;
    throw std::invalid_argument("unknown method '" + name + "' (known: " + method_names(", ") + ")");
}

void register_filter(FilterDescriptor filter) {
    add_filter(std::move(filter));
    for (Method& m : registry()) add_lookup_settings(m);
}

void register_method(Method method) {
    if (find_method(method.name)) throw std::invalid_argument("method '" + method.name + "' is registered already");
    if ((method.compute_maps == nullptr) == (method.compute_geometry == nullptr))
        throw std::invalid_argument("method '" + method.name + "': set exactly one of compute_maps, compute_geometry");
    add_lookup_settings(method);
    registry().push_back(std::move(method));
}

}  // namespace shadowlab
