#include "model/inspection.hpp"

#include <cmath>
#include <stdexcept>

namespace shadowlab {
namespace {

Inspection inspect_map(const Scene& scene, const Method& method, const InspectionRequest& request) {
    if (request.resolution < 1 || request.resolution > 8192)
        throw std::invalid_argument("resolution " + std::to_string(request.resolution) + " is outside 1..8192");
    Inspection in;
    in.scene = scene;
    in.method = &method;
    in.settings = resolve_settings(method.name, method.settings, request.settings);
    in.resolution = request.resolution;
    in.inputs = gather_inputs(scene);
    in.setup = method.compute(in.inputs, in.settings, &in.trace);
    in.triangles = tessellate(scene);
    in.casters = caster_flags(scene);
    in.depth = rasterize_depth(in.triangles, in.casters, in.map(), in.resolution);
    in.bias = request.bias;
    return in;
}

Inspection inspect_geometric(const Scene& scene, const Technique& technique, const InspectionRequest& request) {
    const int width = request.image_width;
    const int height = request.image_height > 0 ? request.image_height
                                                : static_cast<int>(std::lround(width / scene.camera.aspect));
    if (width < 1 || width > 8192 || height < 1 || height > 8192)
        throw std::invalid_argument("camera image " + std::to_string(width) + "x" + std::to_string(height) +
                                    " is outside 1..8192 per side");
    Inspection in;
    in.scene = scene;
    in.settings = resolve_settings(technique.name, technique.settings, request.settings);
    in.inputs = gather_inputs(scene);  // the frustum and the boxes the World view draws
    in.triangles = tessellate(scene);
    in.casters = caster_flags(scene);
    in.technique = inspect_technique(technique, scene, in.triangles, in.settings, width, height, &in.trace);
    return in;
}

}  // namespace

Inspection inspect_scene(const Scene& scene, const InspectionRequest& request) {
    if (const Method* method = find_method(request.method)) return inspect_map(scene, *method, request);
    if (const Technique* technique = find_technique(request.method)) return inspect_geometric(scene, *technique, request);
    throw std::invalid_argument("unknown method '" + request.method + "'");
}

}  // namespace shadowlab
