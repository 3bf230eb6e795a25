#include "methods/cascade_fit.hpp"

#include <algorithm>
#include <cmath>

#include "math/invariant.hpp"

namespace shadowlab {

Frustum depth_slice(const Camera& camera, double near, double far) {
    Camera slice = camera;
    slice.near = near;
    slice.far = far;
    return slice.frustum();
}

Sphere slice_sphere(const Camera& camera, double near, double far) {
    if (camera.is_orthographic())  // a box: its centre, and half its diagonal
        return {.centre = camera.position + (near + far) / 2.0 * camera.view_direction(),
                .radius = std::hypot((far - near) / 2.0, glm::length(camera.half_extent_at(far)))};
    const double k = std::tan(glm::radians(camera.fov_y_deg) / 2.0) * std::sqrt(1.0 + camera.aspect * camera.aspect);
    const double t = std::min((near + far) * (1.0 + k * k) / 2.0, far);
    return {.centre = camera.position + t * camera.view_direction(), .radius = std::hypot(far - t, far * k)};
}

double quantize_up(double length, double unit) {
    assert_invariant(unit > 0.0);  // the scene's bounds are padded never to be flat (gather_inputs)
    const double units = length / unit;
    if (!(units > 0.0)) return length;  // a flat box: nothing to round
    const double step = std::ldexp(1.0, std::ilogb(units) - 6);
    return std::ceil(units / step) * step * unit;
}

SnappedBox snap_to_texels(const Aabb& ls_box, double unit) {
    SnappedBox snapped{.box = ls_box};
    for (int axis = 0; axis < 2; ++axis) {
        // extent' >= extent + one cell: the corner moves down by less than a cell and the box still holds.
        const double extent = quantize_up(ls_box.extent()[axis] * kSnapCells / (kSnapCells - 1.0), unit);
        const double cell = extent / kSnapCells;
        const double corner = std::floor(ls_box.min[axis] / cell) * cell;
        snapped.offset_cells[axis] = (ls_box.min[axis] - corner) / cell;
        snapped.box.min[axis] = corner;
        snapped.box.max[axis] = corner + extent;
    }
    return snapped;
}

}  // namespace shadowlab
