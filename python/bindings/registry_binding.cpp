// The registries as Python data: every method with its settings (core/registry), every view.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "registry/method.hpp"
#include "views/view.hpp"

namespace py = pybind11;

namespace shadowlab::python {
namespace {

py::dict setting_dict(const SettingSpec& spec) {
    py::dict out;
    out["name"] = spec.name;
    out["description"] = spec.description;
    out["default"] = spec.default_value;
    if (spec.is_choice())
        out["choices"] = spec.choices;
    else if (!spec.is_text) {
        out["min"] = spec.min;
        out["max"] = spec.max;
        out["is_list"] = spec.is_list;
    }
    return out;
}

py::dict method_dict(const Method& method) {
    py::dict out;
    out["name"] = method.name;
    out["title"] = method.title;
    out["description"] = method.description;
    out["produces"] = to_string(method.produces());
    out["makes_maps"] = method.makes_maps();
    out["lights"] = method.lights.text();
    py::list settings;
    for (const SettingSpec& spec : method.settings) settings.append(setting_dict(spec));
    out["settings"] = settings;
    return out;
}

}  // namespace

void bind_registry(py::module_& module) {
    module.def(
        "methods",
        [] {
            py::list out;
            for (const Method& method : all_methods()) out.append(method_dict(method));
            return out;
        },
        "Every method --method names, in the registry's order: dicts of name, title, description, produces "
        "('shadow maps' or 'stencil geometry'), makes_maps, lights, and settings (each: name, description, "
        "default, and choices or min, max, is_list).");
    module.def(
        "views",
        [] {
            py::list out;
            for (const View& view : all_views()) out.append(py::make_tuple(view.name, view.title));
            return out;
        },
        "Every view render draws, as (name, title) pairs.");
}

}  // namespace shadowlab::python
