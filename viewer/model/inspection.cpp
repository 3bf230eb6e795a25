#include "model/inspection.hpp"

#include <cmath>

#include "limits.hpp"

namespace shadowlab {

struct Inspection::Judged {
    int width = 0, height = 0;
    ReferenceImage reference;
    std::optional<ShadowError> error;
};

const ReferenceImage& Inspection::reference(int width, int height) const {
    if (!judged_ || judged_->width != width || judged_->height != height)
        judged_ = std::make_shared<Judged>(Judged{width, height, exact_reference(scene, triangles, width, height), {}});
    return judged_->reference;
}

const ShadowError& Inspection::error(int width, int height) const {
    const ReferenceImage& ref = reference(width, height);
    if (!judged_->error)
        judged_->error = has_map() ? measure_shadow_error(scene, ref, depth, setup, bias)
                                   : judge_shadows(scene, ref, geometry->shadowed);
    return *judged_->error;
}

Inspection inspect_scene(const Scene& scene, const InspectionRequest& request) {
    const Method& method = method_or_throw(request.method);
    Inspection in;
    in.scene = scene;
    in.method = &method;
    in.settings = resolve_settings(method.name, method.settings, request.settings);
    in.bias = request.bias;
    in.inputs = gather_inputs(scene);  // the frustum and the boxes the World view draws
    in.triangles = tessellate(scene);
    in.casters = caster_flags(scene);
    if (method.makes_maps()) {
        limits::check(limits::map_resolution, "resolution", request.resolution);
        in.resolution = request.resolution;
        in.setup = method.compute_maps(in.inputs, in.settings, &in.trace);
        in.depth = rasterize_depth(in.triangles, in.casters, in.setup, in.resolution);
    } else {
        in.image_width = request.image_width;
        in.image_height = request.image_height > 0 ? request.image_height
                                                   : static_cast<int>(std::lround(in.image_width / scene.camera.aspect));
        limits::check(limits::image_side, "camera image width", in.image_width);
        limits::check(limits::image_side, "camera image height", in.image_height);
        in.geometry = method.compute_geometry(scene, in.triangles, in.reference(in.image_width, in.image_height),
                                              in.settings, &in.trace);
    }
    return in;
}

}  // namespace shadowlab
