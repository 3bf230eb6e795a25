// A scene file loaded as the commands load it (app/scene_source), refused with the loader's one line.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "scene/light.hpp"

namespace py = pybind11;

namespace shadowlab::python {

void bind_scene(py::module_& module) {
    py::class_<LoadedScene>(module, "Scene",
                            "A scene file (JSON, glTF or a lone mesh) loaded with one of its cameras and lights.")
        .def(py::init([](const std::string& file, size_t camera_index, size_t light_index) {
                 const SceneSource source{.choice = {.camera = camera_index, .light = light_index}};
                 py::gil_scoped_release release;
                 return LoadedScene{.file = file, .source = source, .scene = load_scene_source(file, source)};
             }),
             py::arg("file"), py::arg("camera_index") = 0, py::arg("light_index") = 0,
             "Loads `file`; raises SceneError with the loader's message when it refuses it.")
        .def_readonly("file", &LoadedScene::file, "the file it was loaded from")
        .def_property_readonly(
            "camera_index", [](const LoadedScene& s) { return s.source.choice.camera; }, "the file's camera taken")
        .def_property_readonly(
            "light_index", [](const LoadedScene& s) { return s.source.choice.light; }, "the file's light taken")
        .def_property_readonly(
            "name", [](const LoadedScene& s) { return s.scene.name; }, "the scene's name")
        .def_property_readonly(
            "objects",
            [](const LoadedScene& s) {
                std::vector<std::string> names;
                for (const SceneObject& object : s.scene.objects) names.push_back(object.name);
                return names;
            },
            "its objects' names")
        .def_property_readonly(
            "light", [](const LoadedScene& s) { return std::string(to_string(s.scene.light.type)); },
            "its light's type: directional, spot or point")
        .def_property_readonly(
            "notes", [](const LoadedScene& s) { return loading_notes(s.scene); },
            "what loading left out or degraded, one line each")
        .def("__repr__", [](const LoadedScene& s) {
            return "<shadowlab.Scene " + s.file + ": " + std::to_string(s.scene.objects.size()) + " objects, " +
                   to_string(s.scene.light.type) + " light>";
        });
}

}  // namespace shadowlab::python
