#pragma once
// Where a polygon lands in the camera image: the pixels a geometric technique has to look at for
// it, as a rasterizer's bounding box. The exact per-pixel test is the technique's own.
#include <cstddef>
#include <vector>
#include <glm/glm.hpp>

#include "geometry/homogeneous_clip.hpp"
#include "math/parallel_rows.hpp"
#include "reference/camera_rays.hpp"

namespace shadowlab {

struct PixelBox {
    int x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // inclusive
    bool empty() const { return x1 < x0 || y1 < y0; }
};

// The pixels whose centres the polygon (homogeneous world vertices, w = 0 at infinity) may cover,
// with one pixel of margin: the polygon clipped in clip space to the near plane and the sides of
// the frustum (`world_to_clip` takes the far plane to infinity), then divided by w.
PixelBox pixel_footprint(const glm::dmat4& world_to_clip, const CameraRays& rays, const HomogeneousPolygon& polygon);

// visit(k, x, y, i) for every pixel (x, y), index i, of every box k; rows are shared among the
// cores and each pixel is visited by one thread only, so per-pixel sums need no locks.
template <class Visit>
void for_footprint_pixels(const std::vector<PixelBox>& boxes, int width, Visit&& visit) {
    parallel_rows([&](int first, int stride) {
        for (std::size_t k = 0; k < boxes.size(); ++k) {
            const PixelBox& b = boxes[k];
            for (int y = b.y0 + ((first - b.y0) % stride + stride) % stride; y <= b.y1; y += stride)
                for (int x = b.x0; x <= b.x1; ++x) visit(k, x, y, std::size_t(y) * width + x);
        }
    });
}

}  // namespace shadowlab
