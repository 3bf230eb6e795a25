#include "volumes/stencil_count.hpp"

#include <optional>

#include "math/parallel_rows.hpp"
#include "raster/polygon_spans.hpp"
#include "techniques/pixel_footprint.hpp"

namespace shadowlab {
namespace {

constexpr double kSameDepth = 1e-5;  // relative: a face this near the visible point is behind it

// A volume polygon as the stencil pass draws it: where it lands, and what its fragments add to
// the stencil per the outcome of the depth test (glStencilOp's zfail and zpass operations).
struct StencilFace {
    ScreenPolygon screen;
    PixelBox box;           // the rows (and columns) it may cover
    int on_depth_pass = 0;  // z-pass (Heidmann): front faces increment, back faces decrement
    int on_depth_fail = 0;  // z-fail (Carmack): back faces increment, front faces decrement
    int fragments = 0;      // its multiplicity where the rule draws it
};

// The camera moved to the origin: the view space the faces are rasterized in.
Camera at_origin(const Camera& camera) {
    Camera eye_camera = camera;
    eye_camera.position = glm::dvec3(0.0);
    eye_camera.target = camera.target - camera.position;
    return eye_camera;
}

// Every polygon of the volume set up for rasterization: the caps too, since both counts are kept,
// though only z-fail draws them (z-pass needs none, Heidmann). Set up in view space relative to the
// eye: the edge planes are built from small numbers, and the verdicts do not change when the scene
// stands far away.
std::vector<StencilFace> stencil_faces(const ShadowVolume& volume, const Camera& camera, const CameraRays& rays,
                                       CountRule drawn) {
    const Camera eye_camera = at_origin(camera);
    const glm::dmat4 view_from_eye = eye_camera.view_matrix();  // eye-relative world to view: a rotation
    const glm::dmat4 clip_from_view = eye_camera.infinite_projection_matrix();
    const PixelDirections pixels(eye_camera, rays.width(), rays.height());
    struct Counted {
        const VolumePolygon* polygon;
        bool drawn;
    };
    std::vector<Counted> counted;
    auto add = [&](const std::vector<VolumePolygon>& list, bool is_drawn) {
        for (const VolumePolygon& p : list) counted.push_back({&p, is_drawn});
    };
    add(volume.quads, true);
    add(volume.front_cap, drawn == CountRule::zfail);
    add(volume.back_cap, drawn == CountRule::zfail);

    std::vector<std::optional<StencilFace>> faces(counted.size());
    parallel_rows([&](int first, int stride) {  // the polygons shared among the cores like rows
        HomogeneousPolygon view;
        for (std::size_t k = first; k < counted.size(); k += stride) {
            view.clear();
            for (const glm::dvec4& v : counted[k].polygon->vertices)
                view.push_back(view_from_eye * (v - glm::dvec4(camera.position * v.w, 0.0)));
            std::optional<ScreenPolygon> screen = screen_polygon(view, pixels, camera.near);
            if (!screen) continue;
            const PixelBox box = pixel_footprint(clip_from_view, rays, view);
            if (box.empty()) continue;
            const int m = counted[k].polygon->multiplicity, facing = screen->plane_at_eye > 0.0 ? m : -m;
            faces[k] = StencilFace{.screen = std::move(*screen),
                                   .box = box,
                                   .on_depth_pass = facing,
                                   .on_depth_fail = -facing,
                                   .fragments = counted[k].drawn ? m : 0};
        }
    });
    std::vector<StencilFace> out;
    for (std::optional<StencilFace>& f : faces)
        if (f) out.push_back(std::move(*f));
    return out;
}

// The depth buffer as the stencil pass tests it: per pixel, the largest 1 / view depth a fragment
// may have and still fail the depth test (lie behind the visible point, within kSameDepth). Where
// nothing is visible the buffer keeps its clear value, infinity (bound 0); those counts are dropped.
std::vector<double> depth_fail_bounds(const ReferenceImage& image, const CameraRays& rays) {
    std::vector<double> bound(image.visible.size(), 0.0);
    for (std::size_t i = 0; i < bound.size(); ++i)
        if (image.visible[i]) bound[i] = 1.0 / (rays.view_depth(image.position[i]) * (1.0 - kSameDepth));
    return bound;
}

// The first row at or after y0 that the thread taking rows first, first + stride, ... draws.
int first_row_from(int y0, int first, int stride) { return y0 + ((first - y0) % stride + stride) % stride; }

}  // namespace

StencilCounts count_stencil(const ShadowVolume& volume, const Camera& camera, const ReferenceImage& image,
                            CountRule drawn) {
    const CameraRays rays(camera, image.width, image.height);
    const std::vector<StencilFace> faces = stencil_faces(volume, camera, rays, drawn);
    const std::vector<double> depth_fail_bound = depth_fail_bounds(image, rays);
    const std::size_t pixels = std::size_t(image.width) * image.height;
    StencilCounts c{std::vector<int>(pixels, 0), std::vector<int>(pixels, 0), std::vector<int>(pixels, 0)};
    // The stencil pass, with depth writes off: every face drawn over the pixel centres it covers,
    // its fragments counted by the depth test's outcome, z-pass (Heidmann 1991: front faces +1,
    // back faces -1 where the test passes) and z-fail (Carmack 2000, Everitt and Kilgard 2002: back
    // faces +1, front faces -1 where it fails) at once. Each thread takes a set of rows, so each
    // pixel's sums are one thread's.
    parallel_rows([&](int first, int stride) {
        for (const StencilFace& f : faces)
            for (int y = first_row_from(f.box.y0, first, stride); y <= f.box.y1; y += stride) {
                const Span span = row_span(f.screen, y, f.box.x0, f.box.x1);
                const double depth_along_row = f.screen.inverse_depth.along_row(y);
                const std::size_t row = std::size_t(y) * image.width;
                for (int x = span.first; x <= span.last; ++x) {
                    const std::size_t i = row + x;
                    c.fragments[i] += f.fragments;
                    if (f.screen.inverse_depth.at(x, depth_along_row) <= depth_fail_bound[i])
                        c.zfail[i] += f.on_depth_fail;  // depth test fails: behind the visible point
                    else
                        c.zpass[i] += f.on_depth_pass;  // depth test passes: in front of it
                }
            }
    });
    for (std::size_t i = 0; i < pixels; ++i)
        if (!image.visible[i]) c.zpass[i] = c.zfail[i] = 0;
    return c;
}

}  // namespace shadowlab
