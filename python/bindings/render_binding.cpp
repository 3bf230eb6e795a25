// Any view drawn offscreen as `shadowlab render` draws it (app/render_command), as an RGB array;
// needs an X display (xvfb-run).
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "render_command.hpp"

namespace py = pybind11;

namespace shadowlab::python {
namespace {

py::array_t<uint8_t> rgb_array(const RgbImage& image) {
    return image_array<uint8_t>(image.rgb, image.width, image.height, 3);
}

// render's options by their names (RenderOptions), with its defaults.
py::array_t<uint8_t> render(const LoadedScene& scene, const std::string& method,
                            const std::map<std::string, std::string>& settings, const std::string& view,
                            const std::string& step, int width, int height, int resolution, double bias,
                            const std::string& aliasing, const std::string& error, const std::string& texture,
                            const std::string& light, const std::string& preset, bool scene_in_ppls,
                            const std::string& overlay) {
    const RenderOptions options{.method = method,
                                .settings = settings,
                                .view = view,
                                .step = step,
                                .width = width,
                                .height = height,
                                .resolution = resolution,
                                .bias = bias,
                                .aliasing = aliasing,
                                .error = error,
                                .texture = texture,
                                .light = light,
                                .preset = preset,
                                .scene_in_ppls = scene_in_ppls,
                                .overlay = overlay};
    RgbImage image;
    {
        py::gil_scoped_release release;
        image = render_image(scene.scene, options);
    }
    return rgb_array(image);
}

}  // namespace

void bind_render(py::module_& module) {
    const RenderOptions defaults;
    module.def("render", &render, py::arg("scene"), py::kw_only(), py::arg("method") = defaults.method,
               py::arg("settings") = defaults.settings, py::arg("view") = defaults.view,
               py::arg("step") = defaults.step, py::arg("width") = defaults.width, py::arg("height") = defaults.height,
               py::arg("resolution") = defaults.resolution, py::arg("bias") = defaults.bias,
               py::arg("aliasing") = defaults.aliasing, py::arg("error") = defaults.error,
               py::arg("texture") = defaults.texture, py::arg("light") = defaults.light,
               py::arg("preset") = defaults.preset, py::arg("scene_in_ppls") = defaults.scene_in_ppls,
               py::arg("overlay") = defaults.overlay,
               "A view drawn as `shadowlab render` draws it, by render's options: a height x width x 3 uint8 "
               "array, row 0 at the top. Use shadowlab.render.");
    module.def(
        "read_png", [](const std::string& file) { return rgb_array(read_png(file)); }, py::arg("file"),
        "An 8-bit RGB PNG (as render --out writes them) as a height x width x 3 uint8 array.");
}

}  // namespace shadowlab::python
