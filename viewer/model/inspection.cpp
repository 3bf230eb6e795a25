#include "model/inspection.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>

#include "limits.hpp"
#include "reference/visible_depths.hpp"

namespace shadowlab {

struct Inspection::LazyDepth {
    std::once_flag once;
    DepthMap depth;
};

const DepthMap& Inspection::lazily_rasterized(std::shared_ptr<LazyDepth>& lazy, const std::vector<bool>& drawn) const {
    if (!lazy) lazy = std::make_shared<LazyDepth>();
    std::call_once(lazy->once,
                   [&] { lazy->depth = rasterize_depth(triangles, drawn, setup, resolution, lookup.format); });
    return lazy->depth;
}

const DepthMap& Inspection::depth() const { return lazily_rasterized(depth_, casters); }

const DepthMap& Inspection::surface_depth() const {
    return lazily_rasterized(surface_depth_, std::vector<bool>(scene.objects.size(), true));
}

struct Inspection::Judged {
    int width = 0, height = 0;
    ReferenceImage reference;
    std::optional<ShadowError> error;
};

constexpr size_t kSizesKept = 3;  // a resized window asks for new sizes: the oldest are dropped

Inspection::Judged& Inspection::judged(int width, int height) const {
    if (!judged_) judged_ = std::make_shared<std::deque<Judged>>();
    std::deque<Judged>& kept = *judged_;
    const auto found =
        std::find_if(kept.begin(), kept.end(), [&](const Judged& j) { return j.width == width && j.height == height; });
    if (found != kept.end()) return *found;
    kept.push_front({width, height, light_reference(scene, triangles, width, height), {}});
    if (kept.size() > kSizesKept) kept.pop_back();
    return kept.front();
}

const ReferenceImage& Inspection::reference(int width, int height) const { return judged(width, height).reference; }

const ShadowError& Inspection::error(int width, int height) const {
    Judged& j = judged(width, height);
    if (j.error) return *j.error;
    if (has_map()) {
        const ShadowReader reader(setup, depth(), scene.light, lookup);
        j.error = measure_shadow_error(scene, j.reference, reader, receiver_visibility(scene, j.reference, reader));
    } else {
        j.error = judge_shadows(scene, j.reference, geometry->shadowed);
    }
    return *j.error;
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
    in.image_width = request.image_width;
    in.image_height = request.image_height > 0 ? request.image_height
                                               : static_cast<int>(std::lround(in.image_width / scene.camera.aspect));
    limits::check(limits::image_side, "camera image width", in.image_width);
    limits::check(limits::image_side, "camera image height", in.image_height);
    if (method.makes_maps()) {
        limits::check(limits::map_resolution, "resolution", request.resolution);
        in.resolution = request.resolution;
        in.inputs.texture_resolution = request.resolution;
        if (method.wants_visible_depths(in.settings))
            trace_depth_image(in.inputs, scene, in.triangles, in.image_width, in.image_height);
        in.setup = method.compute_maps(in.inputs, in.settings, &in.trace);
        in.lookup = lookup_from(in.settings, in.bias);
    } else {
        in.geometry = method.compute_geometry(scene, in.triangles, in.reference(in.image_width, in.image_height),
                                              in.settings, &in.trace);
    }
    return in;
}

}  // namespace shadowlab
