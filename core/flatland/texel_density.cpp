#include "flatland/texel_density.hpp"

#include <algorithm>
#include <cmath>

#include "maps/map_lookup.hpp"
#include "math/invariant.hpp"

namespace shadowlab {

std::optional<DepthSpan> view_axis_span(const ShadowInputs& in) {
    const glm::dvec3 eye = in.camera.position, v = in.camera.view_direction();
    DepthSpan span{in.camera.near, in.camera.far};
    for (int a = 0; a < 3; ++a) {  // the slabs of the scene's bounds (Kay and Kajiya)
        if (v[a] == 0.0) {
            if (eye[a] < in.scene_bounds.min[a] || eye[a] > in.scene_bounds.max[a]) return std::nullopt;
            continue;
        }
        const double t0 = (in.scene_bounds.min[a] - eye[a]) / v[a], t1 = (in.scene_bounds.max[a] - eye[a]) / v[a];
        span.near = std::max(span.near, std::min(t0, t1));
        span.far = std::min(span.far, std::max(t0, t1));
    }
    if (!(span.far > span.near)) return std::nullopt;
    return span;
}

std::vector<double> log_spaced_depths(const DepthSpan& span, int count) {
    assert_invariant(span.near > 0.0 && span.far > span.near && count >= 2);
    std::vector<double> depths;
    for (int i = 0; i < count; ++i) depths.push_back(span.near * std::pow(span.far / span.near, i / (count - 1.0)));
    return depths;
}

double ideal_texel_density(const Camera& camera, int image_height, double depth) {
    return image_height / (2.0 * camera.half_extent_at(depth).y);
}

std::vector<DensitySample> texel_density_along_view(const ShadowSetup& setup, const Camera& camera,
                                                    int texture_resolution, int image_height,
                                                    const std::vector<double>& depths) {
    const glm::dvec3 v = camera.view_direction();
    std::vector<DensitySample> samples;
    for (double z : depths) {
        const glm::dvec3 p = camera.position + z * v;
        const std::optional<MapPoint> point = map_point(setup, p);
        if (!point) continue;
        const glm::dvec3 uvz = point->uvz();
        if (glm::any(glm::lessThan(uvz, glm::dvec3(0.0))) || glm::any(glm::greaterThan(uvz, glm::dvec3(1.0)))) continue;
        const ShadowMap& map = setup.maps[point->map];
        const glm::dvec2 per_axis = tile_resolution(map, texture_resolution) * glm::abs(uv_derivative(map, p, v));
        samples.push_back({.depth = z,
                           .map = point->map,
                           .per_axis = per_axis,
                           .texels = glm::length(per_axis),
                           .ideal = ideal_texel_density(camera, image_height, z)});
    }
    return samples;
}

std::vector<DensitySample> texel_density_over_view(const ShadowInputs& in, const ShadowSetup& setup,
                                                   int texture_resolution, int image_height) {
    const std::optional<DepthSpan> span = view_axis_span(in);
    if (!span) return {};
    return texel_density_along_view(setup, in.camera, texture_resolution, image_height,
                                    log_spaced_depths(*span, kDensityDepths));
}

}  // namespace shadowlab
