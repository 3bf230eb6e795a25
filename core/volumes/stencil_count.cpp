#include "volumes/stencil_count.hpp"

#include <cmath>
#include <optional>

#include "geometry/homogeneous_plane.hpp"
#include "reference/camera_rays.hpp"
#include "techniques/pixel_footprint.hpp"

namespace shadowlab {
namespace {

constexpr double kSameDepth = 1e-5;  // relative: a face this near the visible point is behind it

// A volume polygon as seen from one eye.
struct EyePolygon {
    std::vector<glm::dvec3> edge_normals;  // of the planes through the eye and each edge, inside positive
    glm::dvec4 plane;                      // the polygon's, pointing out of the volume
    double plane_at_eye;                   // > 0: the eye sees its outside (front-facing)
    int multiplicity;
    bool drawn;                            // does the counting rule draw it (fill)
};

// Nullopt when the eye lies in the polygon's plane: every eye ray misses it.
std::optional<EyePolygon> seen_from(const VolumePolygon& p, const glm::dvec3& eye, bool drawn) {
    const glm::dvec4 e(eye, 1.0);
    EyePolygon out{{}, polygon_plane(p.vertices), 0.0, p.multiplicity, drawn};
    out.plane_at_eye = glm::dot(out.plane, e);
    if (out.plane_at_eye == 0.0) return std::nullopt;
    glm::dvec4 inside(0.0);  // a point of the polygon: the sum of its vertices
    for (const glm::dvec4& v : p.vertices) inside += v;
    for (std::size_t i = 0; i < p.vertices.size(); ++i) {
        const glm::dvec4 q = plane_through(e, p.vertices[i], p.vertices[(i + 1) % p.vertices.size()]);
        if (q == glm::dvec4(0.0)) continue;  // an edge collapsed at infinity
        const double side = glm::dot(q, inside);
        if (side == 0.0) return std::nullopt;
        out.edge_normals.push_back(glm::dvec3(q) * (side > 0.0 ? 1.0 : -1.0));
    }
    if (out.edge_normals.size() < 3) return std::nullopt;  // collapsed to a segment or a point
    return out;
}

// The ray's t (view depth) where it crosses the polygon, +inf for a crossing at infinity;
// nullopt when it passes by. Inside every edge plane means the line meets the polygon on the
// ray's forward side; its plane then gives t = -(plane . eye) / (plane . direction).
std::optional<double> crossing(const EyePolygon& p, const glm::dvec3& d) {
    for (const glm::dvec3& n : p.edge_normals)
        if (glm::dot(n, d) < 0.0) return std::nullopt;
    const double along = glm::dot(glm::dvec3(p.plane), d);
    return along == 0.0 ? INFINITY : std::abs(p.plane_at_eye / along);
}

}  // namespace

// Counted in eye-relative coordinates: the planes through the eye and each edge are then built from
// small numbers, and the verdicts do not change when the scene stands far from the origin.
StencilCounts count_stencil(const ShadowVolume& volume, const Camera& camera, const ReferenceImage& image,
                            CountRule drawn) {
    Camera eye_camera = camera;
    eye_camera.position = glm::dvec3(0.0);
    eye_camera.target = camera.target - camera.position;
    const CameraRays rays(eye_camera, image.width, image.height);
    const glm::dmat4 eye_to_clip = eye_camera.infinite_projection_matrix() * eye_camera.view_matrix();
    std::vector<EyePolygon> polygons;
    std::vector<PixelBox> boxes;
    auto add = [&](const std::vector<VolumePolygon>& list, bool is_drawn) {
        for (VolumePolygon p : list) {
            p.vertices = translated(std::move(p.vertices), -camera.position);
            if (std::optional<EyePolygon> seen = seen_from(p, rays.eye(), is_drawn)) {
                const PixelBox box = pixel_footprint(eye_to_clip, rays, p.vertices);
                if (box.empty()) continue;
                polygons.push_back(std::move(*seen));
                boxes.push_back(box);
            }
        }
    };
    add(volume.quads, true);
    add(volume.front_cap, drawn == CountRule::zfail);  // z-pass draws no caps (Heidmann)
    add(volume.back_cap, drawn == CountRule::zfail);

    const std::size_t pixels = std::size_t(image.width) * image.height;
    StencilCounts c{std::vector<int>(pixels, 0), std::vector<int>(pixels, 0), std::vector<int>(pixels, 0)};
    for_footprint_pixels(boxes, image.width, [&](std::size_t k, int x, int y, std::size_t i) {
        const EyePolygon& p = polygons[k];
        const std::optional<double> t = crossing(p, rays.direction(x, y));
        if (!t || *t < camera.near) return;  // missed, or clipped by the near plane
        if (p.drawn) c.fragments[i] += p.multiplicity;
        if (!image.visible[i]) return;
        const bool front = p.plane_at_eye > 0.0;
        if (*t >= rays.view_depth(image.position[i] - camera.position) * (1.0 - kSameDepth))
            c.zfail[i] += front ? -p.multiplicity : p.multiplicity;  // depth test fails: behind
        else
            c.zpass[i] += front ? p.multiplicity : -p.multiplicity;  // depth test passes: in front
    });
    return c;
}

}  // namespace shadowlab
