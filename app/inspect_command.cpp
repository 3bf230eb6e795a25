#include "inspect_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "exchange/inspection_json.hpp"
#include "io/value_text.hpp"
#include "maps/projection_kind.hpp"
#include "math/matrix.hpp"
#include "measure_command.hpp"
#include "registry/method.hpp"
#include "reference/exact_shadows.hpp"
#include "reference/visible_depths.hpp"
#include "scene/image_size.hpp"
#include "scene/scene_loader.hpp"
#include "scene/tessellation.hpp"

namespace shadowlab {
namespace {

// A value after its name: on the same line, or a matrix's aligned rows indented below it.
std::string format_value(const TraceValue& value, const std::string& indent) {
    const std::string text = value_text(value);
    if (!std::holds_alternative<glm::dmat4>(value)) return " " + text;
    std::string out;
    size_t start = 0;
    for (size_t end = text.find('\n'); start != std::string::npos; end = text.find('\n', start)) {
        out += "\n" + indent + "  " + text.substr(start, end == std::string::npos ? end : end - start);
        start = end == std::string::npos ? end : end + 1;
    }
    return out;
}

std::string describe(const NamedGeometry& g) {
    return std::visit(
        [](const auto& s) -> std::string {
            using T = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<T, PointSet>)
                return std::to_string(s.points.size()) + " points";
            else if constexpr (std::is_same_v<T, Aabb>)
                return "box" + format_value(s.min, "") + " .." + format_value(s.max, "");
            else if constexpr (std::is_same_v<T, ConvexPolyhedron>)
                return "convex polyhedron, " + std::to_string(s.vertices.size()) + " vertices, " +
                       std::to_string(s.faces.size()) + " faces";
            else if constexpr (std::is_same_v<T, SegmentSet>)
                return std::to_string(s.segments.size()) + " segments";
            else if constexpr (std::is_same_v<T, PolygonSet>) {
                size_t at_infinity = 0;
                for (const glm::dvec4& v : s.vertices) at_infinity += v.w == 0.0;
                return std::to_string(s.polygons.size()) + " polygons, " + std::to_string(at_infinity) + " of " +
                       std::to_string(s.vertices.size()) + " vertices at infinity (w = 0)";
            } else if constexpr (std::is_same_v<T, Arrow>)
                return "arrow" + format_value(s.from, "") + " ->" + format_value(s.to, "");
            else if constexpr (std::is_same_v<T, AngleArc>)
                return "angle at" + format_value(s.centre, "");
            else if constexpr (std::is_same_v<T, Label>)
                return "label \"" + s.text + "\" at" + format_value(s.at, "");
            else
                return "frustum (8 corners)";
        },
        g.geometry);
}

void print_header(const std::string& scene_file, const std::string& name, const std::string& title,
                  const Settings& settings) {
    std::cout << "scene:    " << scene_file << "\n"
              << "method:   " << name << " (" << title << ")\n";
    std::cout << "settings:";
    for (const auto& [key, value] : settings.values())
        std::cout << " " << key << "="
                  << (std::holds_alternative<double>(value) ? Json(std::get<double>(value)).dump()
                                                            : std::get<std::string>(value));
    std::cout << (settings.values().empty() ? " none\n" : "\n");
}

void print_steps(const Trace& trace) {
    int n = 0;
    for (const Step& s : trace.steps()) {
        std::cout << "  " << ++n << ". " << s.title << "  [" << s.id << ", " << to_string(s.space) << " space]\n"
                  << "     " << s.explanation << "\n";
        for (const NamedValue& v : s.values)
            std::cout << "     " << v.name << ":" << format_value(v.value, "     ") << "\n";
        for (const NamedGeometry& g : s.geometry) std::cout << "     " << g.name << ": " << describe(g) << "\n";
    }
}

void print_map(size_t i, const ShadowMap& map) {
    const std::string name = "\nmap " + std::to_string(i);
    const ProjectionKind& kind = projection_kind(map);
    std::cout << name << ": " << kind.name;
    if (kind.numbered_face) std::cout << " " << map.cube_face;
    for (const NamedValue& v : kind.parameters(map))
        std::cout << name << " " << v.name << (std::holds_alternative<glm::dmat4>(v.value) ? " (rows):" : ":")
                  << format_value(v.value, "");
    if (map.viewport != glm::dvec4(0.0, 0.0, 1.0, 1.0))
        std::cout << name << " tile (u0, v0, u1, v1):" << format_value(map.viewport, "");
    std::cout << name << " z_bias_scale: " << map.z_bias_scale << "\n";
}

// Visible depth bounds read a camera depth image of the window's default width.
constexpr int kDepthImageSide = 640;

void inspect_map(const InspectOptions& options, const Method& method, const Settings& settings, const Scene& scene) {
    ShadowInputs inputs = gather_inputs(scene);
    if (method.wants_visible_depths(settings)) {
        const glm::ivec2 image = image_size_within(scene.camera, kDepthImageSide, kDepthImageSide);
        trace_depth_image(inputs, scene, tessellate(scene), image.x, image.y);
    }
    Trace trace;
    const ShadowSetup setup = method.compute_maps(inputs, settings, &trace);
    if (options.json) {
        std::cout << inspection_json(method.name, settings, inputs, setup, trace).dump(1) << "\n";
        return;
    }
    print_header(options.scene_file, method.name, method.title, settings);
    std::cout << "inputs:   " << inputs.receivers.size() << " receiver boxes, " << inputs.casters.size()
              << " caster boxes\n"
              << "fallback: " << (setup.fallbacks.empty() ? "none" : describe(setup.fallbacks)) << "\n\nsteps:\n";
    print_steps(trace);
    if (setup.maps.size() > 1)
        std::cout << "\nmaps: " << setup.maps.size() << ", chosen " << to_string(setup.selection.rule) << "\n";
    for (size_t i = 0; i < setup.maps.size(); ++i) print_map(i, setup.maps[i]);
}

// A technique judges camera pixels: inspect looks through a small image of the camera's aspect.
constexpr int kInspectImageSide = 320;

void inspect_technique(const InspectOptions& options, const Method& technique, const Settings& settings,
                       const Scene& scene) {
    const WorldTriangles triangles = tessellate(scene);
    const glm::ivec2 size = image_size_within(scene.camera, kInspectImageSide, kInspectImageSide);
    const ReferenceImage image = exact_reference(scene, triangles, size.x, size.y);
    Trace trace;
    const GeometryResult result = technique.compute_geometry(scene, triangles, image, settings, &trace);
    if (options.json) {
        std::cout << technique_inspection_json(technique.name, settings, result, trace).dump(1) << "\n";
        return;
    }
    print_header(options.scene_file, technique.name, technique.title, settings);
    std::cout << "image:    " << image.width << "x" << image.height << " (the per-pixel steps)\n"
              << "cost:     " << result.cost.polygons << " polygons, fill mean " << result.cost.fill_mean << ", max "
              << result.cost.fill_max << " fragments per pixel\n"
              << "limits:   " << (result.limits.empty() ? "none" : describe(result.limits)) << "\n\nsteps:\n";
    print_steps(trace);
}

}  // namespace

void run_inspect(const InspectOptions& options) {
    const Method& method = method_or_throw(options.method);
    const Settings settings = resolve_settings(method.name, method.settings, options.settings);
    const Scene scene = load_scene_source(options.scene_file, options.scene_source);
    if (method.makes_maps())
        inspect_map(options, method, settings, scene);
    else
        inspect_technique(options, method, settings, scene);
}

}  // namespace shadowlab
