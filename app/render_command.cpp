#include "render_command.hpp"

#include <iostream>
#include <stdexcept>

#include "limits.hpp"
#include "views/offscreen_view.hpp"
#include "scene/scene_loader.hpp"

namespace shadowlab {
namespace {

ViewKind view_or_throw(const std::string& name) {
    if (const auto view = view_named(name)) return *view;
    std::string names;
    for (ViewKind v : all_views()) names += (names.empty() ? "" : ", ") + std::string(to_string(v));
    throw std::invalid_argument("--view: unknown view '" + name + "' (one of " + names + ")");
}

}  // namespace

void run_render(const RenderOptions& options) {
    limits::check(limits::image_side, "--size width", options.width);
    limits::check(limits::image_side, "--size height", options.height);
    const ViewKind view = view_or_throw(options.view);
    Scene scene = load_scene(options.scene_file);
    scene.camera.aspect = static_cast<double>(options.width) / options.height;  // the image is the camera's
    InspectionRequest request;
    request.method = options.method;
    request.settings = options.settings;
    request.resolution = options.resolution;
    request.bias = options.bias;
    request.image_width = options.width;  // a technique judges the pixels of this very image
    request.image_height = options.height;
    const Inspection inspection = inspect_scene(scene, request);
    if (!inspection.notes().empty())
        std::cerr << (inspection.has_map() ? "fallback: " : "limits: ") << describe(inspection.notes()) << "\n";
    ViewOptions view_options;
    view_options.step = options.step;
    const RgbImage image = render_view(inspection, view, view_options, options.width, options.height);
    write_png(image, options.out);
    std::cerr << "render: " << to_string(view) << " view of " << options.scene_file << " (" << inspection.name();
    if (inspection.has_map())
        std::cerr << ", " << inspection.resolution << "² map, bias "
                  << (inspection.bias < 0.0 ? "slope-scaled" : std::to_string(inspection.bias));
    std::cerr << ") -> " << options.out << "\n";
}

}  // namespace shadowlab
