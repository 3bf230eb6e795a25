// measure and shimmer on a reference traced once per scene and image size (app/measure_command,
// app/shimmer_command): measure --json's text, and the per-pixel images as NumPy arrays.
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "measure_command.hpp"
#include "plot/shimmer_chart.hpp"
#include "shimmer_command.hpp"

namespace py = pybind11;

namespace shadowlab::python {
namespace {

MeasureContext prepare(const LoadedScene& scene, int width, int height) {
    py::gil_scoped_release release;
    return prepare_with_progress(scene.scene, scene.file, width, height);
}

// The reference's own images: what the camera sees and which of it the light reaches.
py::dict reference_arrays(const ReferenceImage& r) {
    py::dict out;
    out["visible"] = image_array<bool>(r.visible, r.width, r.height);
    out["lit"] = image_array<bool>(r.lit, r.width, r.height);
    out["object"] = image_array<int32_t>(r.object, r.width, r.height);
    if (!r.visibility.empty()) out["visibility"] = image_array<float>(r.visibility, r.width, r.height);
    return out;
}

// The judged images: the verdict and, where misclassified, the cause of every pixel (codes named by
// verdict_names and cause_names), m and its factors (0 where not measured).
py::dict error_arrays(const ShadowError& e, int width, int height) {
    py::dict out;
    out["verdicts"] = image_array<uint8_t>(e.verdicts, width, height);
    if (!e.causes.empty()) out["causes"] = image_array<uint8_t>(e.causes, width, height);
    if (!e.m_image.empty()) {
        out["m"] = image_array<float>(e.m_image, width, height);
        out["m_perspective"] = image_array<float>(e.m_perspective_image, width, height);
        out["m_projection"] = image_array<float>(e.m_projection_image, width, height);
    }
    return out;
}

py::tuple measure_on_reference(const MeasureContext& context, const std::string& method, int resolution, double bias,
                               const std::map<std::string, std::string>& settings, bool diagnose) {
    const MeasureOptions options{.method = method, .settings = settings, .resolution = resolution, .bias = bias};
    std::optional<MeasureRun> run;
    {
        py::gil_scoped_release release;
        run = measure_on(context, options, diagnose);
    }
    const ReferenceImage& r = context.reference;
    return py::make_tuple(to_json(*run, context).dump(), error_arrays(run->measurement.error, r.width, r.height));
}

py::dict shimmer_on_reference(const MeasureContext& context, const std::string& method, int resolution,
                              const std::map<std::string, std::string>& settings, const std::string& path, int frames,
                              double step) {
    const ShimmerOptions options{
        .method = method, .settings = settings, .path = path, .frames = frames, .step = step, .resolution = resolution};
    std::optional<Shimmer> shimmer;
    {
        py::gil_scoped_release release;
        shimmer = shimmer_on(context, options);
    }
    py::dict out;
    out["share"] = shimmer->share();
    out["flips"] = shimmer->flips();
    out["transitions"] = shimmer->transitions();
    out["summary"] = shimmer_summary(*shimmer);
    return out;
}

std::vector<std::string> verdict_names() { return {"none", "agree", "false_shadow", "false_light"}; }

std::vector<std::string> cause_names() {
    std::vector<std::string> names(all_causes().size() + 1, to_string(PixelCause::none));
    for (const CauseInfo& cause : all_causes()) names.at(size_t(cause.kind)) = cause.name;
    return names;
}

}  // namespace

void bind_measure(py::module_& module) {
    py::class_<MeasureContext>(module, "Reference",
                               "The exact reference of a scene's camera image (Embree rays), traced once and "
                               "shared by every measure on it.")
        .def(py::init(&prepare), py::arg("scene"), py::arg("width") = 1280, py::arg("height") = 720,
             "Traces the largest image of the camera's aspect within width x height.")
        .def_property_readonly(
            "width", [](const MeasureContext& c) { return c.reference.width; }, "pixels across")
        .def_property_readonly(
            "height", [](const MeasureContext& c) { return c.reference.height; }, "pixels down")
        .def_property_readonly(
            "arrays", [](const MeasureContext& c) { return reference_arrays(c.reference); },
            "visible, lit (bool), object (int32, -1 for none) and, for an area light, visibility (float32): "
            "height x width arrays, row 0 at the top");
    module.def("measure", &measure_on_reference, py::arg("reference"), py::arg("method"), py::arg("resolution"),
               py::arg("bias"), py::arg("settings"), py::arg("diagnose"),
               "(measure --json's text, the per-pixel arrays): use shadowlab.measure.");
    module.def("shimmer", &shimmer_on_reference, py::arg("reference"), py::arg("method"), py::arg("resolution"),
               py::arg("settings"), py::arg("path"), py::arg("frames"), py::arg("step"),
               "shimmer's flips along a camera path: use shadowlab.shimmer.");
    module.def("verdict_names", &verdict_names, "the verdict of each code in measure's 'verdicts' array");
    module.def("cause_names", &cause_names, "the cause of each code in measure's 'causes' array");
}

}  // namespace shadowlab::python
