// A method's result on a scene: inspect --json's object (its maps, selection, steps with their
// values, notes) and, for a map method, every map rasterized into its tile of the texture.
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "exchange/inspection_json.hpp"
#include "model/inspection.hpp"

namespace py = pybind11;

namespace shadowlab::python {
namespace {

// The texture's depths d in [0, 1] (1 where nothing was drawn), row v = 0 first.
py::array_t<float> depth_array(const DepthMap& depth) {
    std::vector<double> values(depth.codes.size());
    for (int y = 0; y < depth.resolution; ++y)
        for (int x = 0; x < depth.resolution; ++x) values[depth.index(x, y)] = depth.at(x, y);
    return image_array<float>(values, depth.resolution, depth.resolution);
}

py::tuple compute(const LoadedScene& scene, const std::string& method,
                  const std::map<std::string, std::string>& settings, int resolution, double bias, bool rasterize) {
    std::optional<Inspection> inspection;
    std::string json;
    {
        py::gil_scoped_release release;
        inspection = inspect_scene(scene.scene,
                                   {.method = method, .settings = settings, .resolution = resolution, .bias = bias});
        const Inspection& i = *inspection;
        json = (i.has_map() ? inspection_json(i.name(), i.settings, i.inputs, i.setup, i.trace)
                            : technique_inspection_json(i.name(), i.settings, *i.geometry, i.trace))
                   .dump();
        if (rasterize && i.has_map()) i.depth();
    }
    if (!rasterize || !inspection->has_map()) return py::make_tuple(json, py::none());
    return py::make_tuple(json, depth_array(inspection->depth()));
}

}  // namespace

void bind_setup(py::module_& module) {
    module.def("compute", &compute, py::arg("scene"), py::arg("method"), py::arg("settings"), py::arg("resolution"),
               py::arg("bias"), py::arg("rasterize"),
               "(inspect --json's text, the maps' depth texture or None): use shadowlab.compute.");
}

}  // namespace shadowlab::python
