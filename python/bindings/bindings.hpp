#pragma once
// The compiled half of the Python package `shadowlab` (python/shadowlab/__init__.py is the other):
// thin bindings of the app's commands and core's registry, one file per concept. Results cross as
// the CLI's own JSON text (the Python half parses it) and images as NumPy arrays.
#include <pybind11/pybind11.h>

#include "scene_source.hpp"

namespace shadowlab::python {

// A scene file loaded as a command loads it: the file, which of its cameras and lights, the scene.
struct LoadedScene {
    std::string file;
    SceneSource source;
    Scene scene;
};

void bind_registry(pybind11::module_& module);  // methods, views
void bind_scene(pybind11::module_& module);     // Scene
void bind_setup(pybind11::module_& module);     // compute: inspect --json, the rasterized maps
void bind_measure(pybind11::module_& module);   // Reference, measure, shimmer
void bind_render(pybind11::module_& module);    // render, read_png

}  // namespace shadowlab::python
