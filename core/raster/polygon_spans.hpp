#pragma once
// Convex polygons with homogeneous vertices scan-converted at the camera's pixel centres without a
// division by w (Olano and Greer 1997, "Triangle scan conversion using 2D homogeneous
// coordinates"): the eye and an edge span a plane, which meets the image in a line, the edge
// function; a polygon covers the pixels inside all its edge lines. Vertices behind the eye or at
// infinity (w = 0) need no special case, and the near plane is one more line, where the polygon's
// 1 / view depth, affine over the image (perspective-correct), reaches 1 / near.
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>
#include <glm/glm.hpp>

#include "geometry/homogeneous_clip.hpp"
#include "geometry/homogeneous_plane.hpp"
#include "scene/camera.hpp"

namespace shadowlab {

// An affine function of the pixel coordinates (pixel centres at integers, row 0 at the top).
struct PixelLinear {
    double a = 0.0, b = 0.0, c = 0.0;  // a x + b y + c

    double along_row(int y) const { return b * y + c; }
    double at(int x, double row_value) const { return a * x + row_value; }
};

// The view-space direction through pixel (x, y), at view depth 1 (z = -1) like CameraRays::direction:
// affine in x and y, so a view-space linear form n . d becomes the pixel function of `of(n)`.
struct PixelDirections {
    glm::dvec3 origin, per_x, per_y;  // d(x, y) = origin + x per_x + y per_y

    PixelDirections(const Camera& camera, int width, int height) {
        const glm::dmat4 projection = camera.projection_matrix();
        const double focal_x = projection[0][0], focal_y = projection[1][1];
        // ndc x = 2 (x + 0.5) / width - 1, ndc y = 1 - 2 (y + 0.5) / height, d = (ndc x / fx, ndc y / fy, -1)
        origin = {(1.0 / width - 1.0) / focal_x, (1.0 - 1.0 / height) / focal_y, -1.0};
        per_x = {2.0 / (width * focal_x), 0.0, 0.0};
        per_y = {0.0, -2.0 / (height * focal_y), 0.0};
    }
    // Exactly odd in n: the two polygons sharing an edge get exactly opposite edge functions.
    PixelLinear of(const glm::dvec3& n) const { return {glm::dot(n, per_x), glm::dot(n, per_y), glm::dot(n, origin)}; }
};

// One side of a line: covered where the function is > 0, and where it is exactly 0 only if the
// top-left rule gives it the line, so that of two polygons sharing an edge (opposite functions)
// exactly one covers a pixel centre on it.
struct HalfPlane {
    PixelLinear f;
    bool owns_line;

    bool covers(double value) const { return value > 0.0 || (value == 0.0 && owns_line); }
};

// The top-left rule (as in Direct3D): a left edge (inside to its right, a > 0), or a top edge
// (horizontal, inside below it: rows grow downward).
inline HalfPlane inside_of(const PixelLinear& f) { return {f, f.a > 0.0 || (f.a == 0.0 && f.b > 0.0)}; }

// A convex polygon as the camera's rasterizer sees it.
struct ScreenPolygon {
    std::vector<HalfPlane> sides;  // its edge lines, then the near plane's line where that cuts it
    PixelLinear inverse_depth;     // 1 / view depth of its point on each pixel's ray (0 at infinity)
    double plane_at_eye;           // its plane at the eye: > 0 when the eye sees the side its plane points to
};

// The polygon from its view-space vertices (the eye at the origin, looking down -z); nullopt when
// the eye lies in its plane (every eye ray misses it) or it is seen as a segment or a point.
inline std::optional<ScreenPolygon> screen_polygon(const HomogeneousPolygon& view_vertices,
                                                   const PixelDirections& pixels, double near) {
    const glm::dvec4 plane = polygon_plane(view_vertices);
    if (plane.w == 0.0) return std::nullopt;
    // A point x d on the ray d(x, y) lies in the plane where x (plane.xyz . d) + plane.w = 0.
    ScreenPolygon out{{}, pixels.of(-glm::dvec3(plane) / plane.w), plane.w};
    out.sides.reserve(view_vertices.size() + 1);
    glm::dvec3 inside(0.0);  // the direction from the eye to a point of the polygon: the sum of its vertices
    for (const glm::dvec4& v : view_vertices) inside += glm::dvec3(v);
    for (std::size_t i = 0; i < view_vertices.size(); ++i) {
        // The plane through the eye and the edge; a point at infinity (d, 0) lies on the eye's line
        // through d like a finite point, so no w is needed. cross(b, a) is exactly -cross(a, b).
        const glm::dvec3 n =
            glm::cross(glm::dvec3(view_vertices[i]), glm::dvec3(view_vertices[(i + 1) % view_vertices.size()]));
        if (n == glm::dvec3(0.0)) continue;  // an edge collapsed at infinity, or seen end-on
        const double side = glm::dot(n, inside);
        if (side == 0.0) return std::nullopt;
        out.sides.push_back(inside_of(pixels.of(side > 0.0 ? n : -n)));
    }
    if (out.sides.size() < 3) return std::nullopt;
    // Clipped by the near plane as on a GPU, where it cuts the polygon (a vertex lies nearer than
    // it, view depth -z < near w): kept where the view depth >= near, 1 / depth <= 1 / near.
    const auto nearer = [near](const glm::dvec4& v) { return -v.z < near * v.w; };
    if (std::any_of(view_vertices.begin(), view_vertices.end(), nearer)) {
        const PixelLinear& q = out.inverse_depth;
        out.sides.push_back({{-q.a, -q.b, 1.0 / near - q.c}, true});
    }
    for (const HalfPlane& h : out.sides)
        if (!std::isfinite(h.f.a) || !std::isfinite(h.f.b) || !std::isfinite(h.f.c)) return std::nullopt;
    return out;
}

// A run of pixels on one row, first to last (inclusive).
struct Span {
    int first = 0, last = -1;
    bool empty() const { return last < first; }
};

// The pixels of row y, within [x0, x1], whose centres the polygon covers. Along a row each side's
// test is monotone, so the covered pixels are one run; a division finds each side's crossing and
// the side's own test at the pixels around it settles the rounding, so the run holds exactly the
// pixels that pass every test (and shared edges stay watertight).
inline Span row_span(const ScreenPolygon& p, int y, int x0, int x1) {
    Span s{x0, x1};
    for (const HalfPlane& h : p.sides) {
        const double row = h.f.along_row(y);
        if (h.f.a == 0.0) {
            if (!h.covers(row)) return {};
            continue;
        }
        const auto covers = [&](int x) { return h.covers(h.f.at(x, row)); };
        // Most sides do not bound most rows: the run's end nearest the line already passes.
        if (covers(h.f.a > 0.0 ? s.first : s.last)) continue;
        const double crossing = std::clamp(-row / h.f.a, x0 - 1.0, x1 + 1.0);
        if (h.f.a > 0.0) {  // covered from the crossing rightward
            int x = int(std::ceil(crossing));
            while (x > s.first && covers(x - 1)) --x;
            while (x <= s.last && !covers(x)) ++x;
            s.first = std::max(s.first, x);
        } else {  // covered from the crossing leftward
            int x = int(std::floor(crossing));
            while (x < s.last && covers(x + 1)) ++x;
            while (x >= s.first && !covers(x)) --x;
            s.last = std::min(s.last, x);
        }
        if (s.empty()) return {};
    }
    return s;
}

}  // namespace shadowlab
