#include "render_command.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "limits.hpp"
#include "scene/image_size.hpp"
#include "scene/light.hpp"
#include "views/offscreen_view.hpp"
#include "scene/scene_loader.hpp"

namespace shadowlab {
namespace {

AliasingShown aliasing_or_throw(const std::string& name) {
    if (name == "total") return AliasingShown::total;
    if (name == "perspective") return AliasingShown::perspective;
    if (name == "projection") return AliasingShown::projection;
    throw std::invalid_argument("--aliasing: unknown '" + name + "' (one of total, perspective, projection)");
}

ErrorShown error_or_throw(const std::string& name) {
    if (const auto shown = error_shown_named(name)) return *shown;
    std::string names;
    for (const ErrorChoice& c : all_error_choices()) names += (names.empty() ? "" : ", ") + std::string(c.name);
    throw std::invalid_argument("--error: unknown '" + name + "' (one of " + names + ")");
}

TextureShown texture_or_throw(const std::string& name) {
    if (name == "depth") return TextureShown::depth;
    if (name == "mean") return TextureShown::moment_mean;
    if (name == "deviation") return TextureShown::moment_deviation;
    throw std::invalid_argument("--texture: unknown '" + name + "' (one of depth, mean, deviation)");
}

MapOverlay overlay_or_throw(const std::string& name) {
    if (name == "none") return MapOverlay::none;
    if (name == "cascade") return MapOverlay::cascade_index;
    if (name == "texels") return MapOverlay::texels_per_pixel;
    throw std::invalid_argument("--overlay: unknown '" + name + "' (one of none, cascade, texels)");
}

SpacePreset preset_or_throw(const std::string& name) {
    if (const auto preset = space_preset_named(name)) return *preset;
    std::string names;
    for (SpacePreset p : all_space_presets()) names += (names.empty() ? "" : ", ") + std::string(to_string(p));
    throw std::invalid_argument("--preset: unknown preset '" + name + "' (one of " + names + ")");
}

// "AZ,EL" in degrees: azimuth about +y from +x toward +z, elevation above the ground plane, as the
// window's Controls panel reads its sliders (light_direction_from_angles).
glm::dvec3 light_direction_or_throw(const std::string& text) {
    double azimuth = 0.0, elevation = 0.0;
    char end = 0;
    if (std::sscanf(text.c_str(), "%lf,%lf%c", &azimuth, &elevation, &end) != 2 || !std::isfinite(azimuth) ||
        !std::isfinite(elevation))
        throw std::invalid_argument("--light: expected AZ,EL in degrees (e.g. 120,35), got '" + text + "'");
    if (elevation < -90.0 || elevation > 90.0)
        throw std::invalid_argument("--light: elevation " + text.substr(text.find(',') + 1) +
                                    " is outside -90..90 (degrees above the ground plane)");
    return light_direction_from_angles(azimuth, elevation);
}

// The scene's light turned to --light; a point light has no direction to turn.
void turn_light(Scene& scene, const std::string& angles) {
    if (angles.empty()) return;
    const glm::dvec3 direction = light_direction_or_throw(angles);
    if (scene.light.type == LightType::point)
        throw std::invalid_argument("--light: the scene's light is a point light, which has no direction");
    scene.light.direction = direction;
}

}  // namespace

RgbImage render_image(Scene scene, const RenderOptions& options) {
    limits::check(limits::image_side, "--size width", options.width);
    limits::check(limits::image_side, "--size height", options.height);
    const View* view = find_view(options.view);
    if (!view) throw std::invalid_argument("--view: unknown view '" + options.view + "' (one of " + view_names() + ")");
    const AliasingShown aliasing = aliasing_or_throw(options.aliasing);
    const ErrorShown error = error_or_throw(options.error);
    const TextureShown texture = texture_or_throw(options.texture);
    const SpacePreset preset = preset_or_throw(options.preset);
    const MapOverlay overlay = overlay_or_throw(options.overlay);
    turn_light(scene, options.light);
    // The camera keeps its aspect: its image is the largest of that shape within --size; the Camera
    // view is drawn at that size, the other views fill --size (their images are letterboxed).
    const glm::ivec2 camera_image = image_size_within(scene.camera, options.width, options.height);
    const glm::ivec2 size =
        view->interaction.through_scene_camera ? camera_image : glm::ivec2(options.width, options.height);
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
    view_options.error = error;
    view_options.texture = texture;
    view_options.preset = preset;
    view_options.scene_in_ppls = options.scene_in_ppls;
    view_options.overlay = overlay;
    return render_view(inspection, *view, view_options, size.x, size.y);
}

void run_render(const RenderOptions& options) {
    const RgbImage image = render_image(load_scene_source(options.scene_file, options.scene_source), options);
    write_png(image, options.out);
    const Method& method = method_or_throw(options.method);
    std::cerr << "render: " << options.view << " view of " << options.scene_file << " (" << method.name;
    if (method.makes_maps())
        std::cerr << ", " << options.resolution << "² map, bias "
                  << (options.bias < 0.0 ? "slope-scaled" : std::to_string(options.bias));
    std::cerr << ") -> " << options.out << ", " << image.width << "x" << image.height;
    if (glm::ivec2(image.width, image.height) != glm::ivec2(options.width, options.height))
        std::cerr << " (the camera's aspect within --size)";
    std::cerr << "\n";
}

}  // namespace shadowlab
