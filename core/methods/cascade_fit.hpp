#pragma once
// What a cascade's light box is fit to, and how it is kept still: the camera's frustum cut to the
// cascade's depths, its bounding sphere (whose size no camera rotation changes), and the snap of a
// light-space box to whole texels (so that a camera translation moves the map by whole texels only:
// nothing shimmers; Valient 2008, the DirectX SDK's CascadedShadowMaps sample).
#include <glm/glm.hpp>

#include "geometry/aabb.hpp"
#include "geometry/frustum.hpp"
#include "scene/camera.hpp"

namespace shadowlab {

// The camera's frustum between view depths `near` and `far` (its own shape, cut).
Frustum depth_slice(const Camera& camera, double near, double far);

struct Sphere {
    glm::dvec3 centre{0.0};
    double radius = 0.0;
};

// The smallest sphere through the slice's corners. The frustum is symmetric, so the centre lies on
// its axis at t where the near and far corners are equally far, (t - n)² + (n k)² = (f - t)² + (f k)²
// (k = tan(fov/2) sqrt(1 + aspect²)): t = (n + f)(1 + k²)/2, at most f. Its radius depends on n, f, the
// field of view and the aspect only: not on where the camera looks. An orthographic camera's slice is
// a box: centred at t = (n + f)/2, its radius half the box's diagonal.
Sphere slice_sphere(const Camera& camera, double near, double far);

// The snap grid: 256 cells per tile side. A tile of any multiple of 256 texels per side (a 512²
// atlas of 2 x 2 tiles and up) then moves by whole texels when the box moves by whole cells.
constexpr int kSnapCells = 256;

// A length rounded up to a multiple of 1/64 of its power of two, counted in `unit`s (the scene's
// size, so that the same scene scaled rounds alike): lengths that differ by rounding noise (a
// sphere's radius for two camera turns) give the same value, within 1/64 of the length.
double quantize_up(double length, double unit);

// The light-space box with its x and y extents quantized and its corner moved down onto the grid of
// extent / kSnapCells (the grid's lines then hold the light space's origin: the cascades put it at the
// scene's centre):
// the extent grows by a cell first, so the moved box still holds the original.
struct SnappedBox {
    Aabb box;
    glm::dvec2 offset_cells{0.0};  // how far the corner moved, in grid cells ([0, 1) each)
};
SnappedBox snap_to_texels(const Aabb& ls_box, double unit);

}  // namespace shadowlab
