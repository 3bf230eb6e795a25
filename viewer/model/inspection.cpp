#include "model/inspection.hpp"

#include <stdexcept>

namespace shadowlab {

Inspection inspect_scene(const Scene& scene, const InspectionRequest& request) {
    const Method* method = find_method(request.method);
    if (!method) throw std::invalid_argument("unknown method '" + request.method + "'");
    if (request.resolution < 1 || request.resolution > 8192)
        throw std::invalid_argument("resolution " + std::to_string(request.resolution) + " is outside 1..8192");
    Inspection in;
    in.scene = scene;
    in.method = method;
    in.settings = resolve_settings(method->name, method->settings, request.settings);
    in.resolution = request.resolution;
    in.inputs = gather_inputs(scene);
    in.setup = method->compute(in.inputs, in.settings, &in.trace);
    in.triangles = tessellate(scene);
    in.casters = caster_flags(scene);
    in.depth = rasterize_depth(in.triangles, in.casters, in.map(), in.resolution);
    in.bias = request.bias;
    return in;
}

}  // namespace shadowlab
