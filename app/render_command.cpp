#include "render_command.hpp"

#include <iostream>
#include <stdexcept>

#include "limits.hpp"
#include "scene/image_size.hpp"
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

AliasingShown aliasing_or_throw(const std::string& name) {
    if (name == "total") return AliasingShown::total;
    if (name == "perspective") return AliasingShown::perspective;
    if (name == "projection") return AliasingShown::projection;
    throw std::invalid_argument("--aliasing: unknown '" + name + "' (one of total, perspective, projection)");
}

}  // namespace

void run_render(const RenderOptions& options) {
    limits::check(limits::image_side, "--size width", options.width);
    limits::check(limits::image_side, "--size height", options.height);
    const ViewKind view = view_or_throw(options.view);
    const AliasingShown aliasing = aliasing_or_throw(options.aliasing);
    const Scene scene = load_scene(options.scene_file);
    // The camera keeps its aspect: its image is the largest of that shape within --size; the Camera
    // view is drawn at that size, the other views fill --size (their images are letterboxed).
    const glm::ivec2 camera_image = image_size_within(scene.camera, options.width, options.height);
    const glm::ivec2 size = view == ViewKind::camera ? camera_image : glm::ivec2(options.width, options.height);
    InspectionRequest request;
    request.method = options.method;
    request.settings = options.settings;
    request.resolution = options.resolution;
    request.bias = options.bias;
    request.image_width = camera_image.x;  // a technique judges the pixels of the camera's image
    request.image_height = camera_image.y;
    const Inspection inspection = inspect_scene(scene, request);
    if (!inspection.notes().empty())
        std::cerr << (inspection.has_map() ? "fallback: " : "limits: ") << describe(inspection.notes()) << "\n";
    ViewOptions view_options;
    view_options.step = options.step;
    view_options.aliasing = aliasing;
    const RgbImage image = render_view(inspection, view, view_options, size.x, size.y);
    write_png(image, options.out);
    std::cerr << "render: " << to_string(view) << " view of " << options.scene_file << " (" << inspection.name();
    if (inspection.has_map())
        std::cerr << ", " << inspection.resolution << "² map, bias "
                  << (inspection.bias < 0.0 ? "slope-scaled" : std::to_string(inspection.bias));
    std::cerr << ") -> " << options.out << ", " << size.x << "x" << size.y;
    if (size != glm::ivec2(options.width, options.height)) std::cerr << " (the camera's aspect within --size)";
    std::cerr << "\n";
}

}  // namespace shadowlab
