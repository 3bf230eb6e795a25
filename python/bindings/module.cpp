// The module _shadowlab: core's errors as Python exceptions with the CLI's one-line messages, and
// the bindings of bindings.hpp.
#include "bindings.hpp"
#include "scene/scene_error.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_shadowlab, module) {
    module.doc() = "ShadowLab's compiled core: use the package shadowlab, which wraps it.";
    // A scene the loader refuses; std::invalid_argument (a bad method, setting, size) is ValueError
    // and std::runtime_error (no X display, a file not written) RuntimeError, as pybind11 maps them.
    py::register_exception<shadowlab::SceneError>(module, "SceneError", PyExc_ValueError);
    shadowlab::python::bind_registry(module);
    shadowlab::python::bind_scene(module);
    shadowlab::python::bind_setup(module);
    shadowlab::python::bind_measure(module);
    shadowlab::python::bind_render(module);
}
