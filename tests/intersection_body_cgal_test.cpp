// The CGAL intersection body (epick and epeck): closed-form volumes, containment, agreement of the
// two kernels, and degenerate inputs.
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "geometry/intersection_body.hpp"

namespace shadowlab {
namespace {

// Plane through a, b, c whose normal points away from `inside`.
Plane plane_through(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& inside) {
    Plane p = Plane::through(a, glm::cross(b - a, c - a));
    return p.signed_distance(inside) > 0.0 ? Plane{-p.normal, -p.offset} : p;
}

// A perspective frustum with corners and outward planes (near, far, left, right, bottom, top).
Frustum make_frustum(glm::dvec3 eye, glm::dvec3 dir, glm::dvec3 up, double fov_y_deg, double aspect, double near,
                     double far) {
    dir = glm::normalize(dir);
    const glm::dvec3 right = glm::normalize(glm::cross(dir, up));
    const glm::dvec3 image_up = glm::cross(right, dir);
    const double t = std::tan(glm::radians(fov_y_deg) / 2.0);
    Frustum f;
    for (int i = 0; i < 8; ++i) {
        const double d = i < 4 ? near : far;
        const double sx = (i % 4 == 1 || i % 4 == 2) ? 1.0 : -1.0, sy = (i % 4 >= 2) ? 1.0 : -1.0;
        f.corners[i] = eye + d * dir + sx * d * t * aspect * right + sy * d * t * image_up;
    }
    const glm::dvec3 mid = eye + 0.5 * (near + far) * dir;
    const auto& c = f.corners;
    f.planes = {plane_through(c[0], c[1], c[2], mid), plane_through(c[4], c[5], c[6], mid),
                plane_through(eye, c[0], c[3], mid),  plane_through(eye, c[1], c[2], mid),
                plane_through(eye, c[0], c[1], mid),  plane_through(eye, c[2], c[3], mid)};
    return f;
}

Aabb box(glm::dvec3 min, glm::dvec3 max) { return Aabb{min, max}; }

// Finite unit normals, and each face's own vertices on its plane (is_convex covers the rest).
testing::AssertionResult planes_sound(const ConvexPolyhedron& p, double tolerance) {
    for (std::size_t k = 0; k < p.faces.size(); ++k) {
        const PolyFace& f = p.faces[k];
        if (!std::isfinite(f.plane.offset) || !(std::abs(glm::length(f.plane.normal) - 1.0) <= 1e-12))
            return testing::AssertionFailure() << "face " << k << " has a bad plane";
        for (int i : f.loop)
            if (!(std::abs(f.plane.signed_distance(p.vertices[i])) <= tolerance))
                return testing::AssertionFailure() << "vertex " << i << " is off its face " << k;
    }
    return testing::AssertionSuccess();
}

bool inside(const ConvexPolyhedron& inner, const ConvexPolyhedron& outer, double tolerance) {
    for (const glm::dvec3& v : inner.vertices)
        for (const PolyFace& f : outer.faces)
            if (!(f.plane.signed_distance(v) <= tolerance)) return false;
    return true;
}

// The checks every non-empty result must pass.
void expect_valid(const IntersectionBody& r, const BodyInput& in) {
    const double tol = 1e-9 * in.scene_bounds.diagonal();
    ASSERT_FALSE(r.visible.empty());
    ASSERT_FALSE(r.body.empty());
    EXPECT_TRUE(is_closed(r.visible));
    EXPECT_TRUE(is_closed(r.body));
    EXPECT_TRUE(is_convex(r.visible, tol));
    EXPECT_TRUE(is_convex(r.body, tol));
    EXPECT_TRUE(planes_sound(r.visible, tol));
    EXPECT_TRUE(planes_sound(r.body, tol));
    EXPECT_TRUE(inside(r.visible, r.body, tol));                                                // V ⊂ B
    for (const glm::dvec3& v : r.body.vertices) EXPECT_TRUE(in.scene_bounds.contains(v, tol));  // B ⊂ S
    for (const glm::dvec3& v : r.visible.vertices) EXPECT_TRUE(in.frustum.contains(v, tol));    // V ⊂ F
    EXPECT_GT(r.visible.volume(), 0.0);
    EXPECT_GE(r.body.volume(), r.visible.volume() * (1.0 - 1e-9));
}

void expect_empty(const IntersectionBody& r) {
    EXPECT_TRUE(r.visible.empty());
    EXPECT_TRUE(r.body.empty());
}

// Area of a frustum cross-section at distance d.
double section(double d, double fov_y_deg, double aspect) {
    const double h = 2.0 * d * std::tan(glm::radians(fov_y_deg) / 2.0);
    return h * h * aspect;
}

// Both kernels on one input: the same emptiness, valid results, volumes within 1e-9. True when
// the body is not empty.
bool kernels_agree(const BodyInput& in) {
    const IntersectionBody inexact = intersection_body_cgal(in, false);
    const IntersectionBody exact = intersection_body_cgal(in, true);
    EXPECT_EQ(inexact.visible.empty(), exact.visible.empty());
    if (exact.visible.empty()) {
        expect_empty(inexact);
        expect_empty(exact);
        return false;
    }
    expect_valid(inexact, in);
    expect_valid(exact, in);
    EXPECT_NEAR(inexact.visible.volume(), exact.visible.volume(), 1e-9 * exact.visible.volume());
    EXPECT_NEAR(inexact.body.volume(), exact.body.volume(), 1e-9 * exact.body.volume());
    return true;
}

TEST(BodyCgal, FrustumEnclosingSceneGivesScene) {
    const Aabb s = box({-2, -1, -3}, {2, 1, 3});
    const Frustum f = make_frustum({0, 0, 50}, {0, 0, -1}, {0, 1, 0}, 60, 1.0, 1.0, 200.0);
    for (glm::dvec4 light : {glm::dvec4(0, 1, 0, 0), glm::dvec4(0, 10, 0, 1), glm::dvec4(0.3, 1, 0.2, 0)})
        for (bool exact : {false, true}) {
            const BodyInput in{f, s, light};
            const IntersectionBody r = intersection_body_cgal(in, exact);
            expect_valid(r, in);
            EXPECT_NEAR(r.visible.volume(), 48.0, 1e-9);
            EXPECT_NEAR(r.body.volume(), 48.0, 1e-9);
            if (glm::dvec3(light) == glm::dvec3(0, 1, 0)) {
                EXPECT_EQ(r.visible.faces.size(), 6u);  // coplanar triangles merged into the 6 quads
                EXPECT_EQ(r.body.vertices.size(), 8u);
            }
        }
}

TEST(BodyCgal, FrustumInsideSceneHasClosedFormVolumes) {
    const Aabb s = box({-10, -10, -10}, {10, 10, 10});
    const double fov = 60, aspect = 1.5, near = 1, far = 8;  // far plane at z = -3
    const Frustum f = make_frustum({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, fov, aspect, near, far);
    const double a1 = section(near, fov, aspect), a2 = section(far, fov, aspect);
    const double v = (far - near) / 3.0 * (a1 + a2 + std::sqrt(a1 * a2));
    struct Case {
        glm::dvec4 light;
        double body;
    };
    const Case cases[] = {
        {{0, 0, 1, 0}, a2 * 13.0},        // light behind the camera: far rectangle swept to z = 10
        {{0, 0, -1, 0}, v + a2 * 7.0},    // light in front: V plus the far rectangle swept to z = -10
        {{0, 0, 5, 1}, a2 * far / 3.0},   // point light at the eye: the whole pyramid
        {{0, 0, 10, 2}, a2 * far / 3.0},  // the same point, homogeneous with w = 2
        {{0, 0, 0, 0}, v},                // no direction: B = V
    };
    for (const Case& c : cases)
        for (bool exact : {false, true}) {
            SCOPED_TRACE(testing::Message() << "light " << c.light.x << ' ' << c.light.y << ' ' << c.light.z << ' '
                                            << c.light.w << (exact ? " epeck" : " epick"));
            const BodyInput in{f, s, c.light};
            const IntersectionBody r = intersection_body_cgal(in, exact);
            expect_valid(r, in);
            EXPECT_NEAR(r.visible.volume(), v, 1e-9 * v);
            EXPECT_NEAR(r.body.volume(), c.body, 1e-9 * c.body);
        }
}

TEST(BodyCgal, FarPlaneOnSceneFace) {
    // V = the frustum, its far face lying on S's bottom face z = -10.
    const Aabb s = box({-10, -10, -10}, {10, 10, 10});
    const Frustum f = make_frustum({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 60, 1.0, 1.0, 15.0);
    const double a1 = section(1, 60, 1), a2 = section(15, 60, 1);
    const double v = 14.0 / 3.0 * (a1 + a2 + std::sqrt(a1 * a2));
    for (bool exact : {false, true}) {
        const BodyInput in{f, s, {0.2, -0.1, 1, 0}};
        const IntersectionBody r = intersection_body_cgal(in, exact);
        expect_valid(r, in);
        EXPECT_NEAR(r.visible.volume(), v, 1e-9 * v);
    }
}

TEST(BodyCgal, FrustumMissingSceneIsEmpty) {
    const Aabb s = box({-1, -1, -1}, {1, 1, 1});
    const Frustum away = make_frustum({0, 0, 5}, {0, 0, 1}, {0, 1, 0}, 60, 1.0, 0.1, 100);
    const Frustum short_of = make_frustum({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 60, 1.0, 0.1, 3.9);
    const Frustum beside = make_frustum({5, 0, 5}, {0, 0, -1}, {0, 1, 0}, 20, 1.0, 0.1, 100);
    // Contact without volume: the far plane on S's top face, the frustum above it.
    const Frustum touching = make_frustum({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 60, 1.0, 0.1, 4.0);
    for (const Frustum& f : {away, short_of, beside, touching})
        for (bool exact : {false, true}) expect_empty(intersection_body_cgal({f, s, {0, 1, 0, 0}}, exact));
}

TEST(BodyCgal, DegenerateInputs) {
    const Frustum f = make_frustum({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 60, 1.0, 0.5, 20);
    const Aabb s = box({-3, -3, -3}, {3, 3, 3});
    for (bool exact : {false, true}) {
        // A flat scene box (zero extent in z) or an empty one: empty body, no padding.
        expect_empty(intersection_body_cgal({f, box({-3, -3, 0}, {3, 3, 0}), {0, 1, 0, 0}}, exact));
        expect_empty(intersection_body_cgal({f, Aabb{}, {0, 1, 0, 0}}, exact));
        // Non-finite input: empty.
        expect_empty(intersection_body_cgal({f, s, {NAN, 1, 0, 0}}, exact));
        expect_empty(intersection_body_cgal({f, s, {0, 1, 0, 1e-320}}, exact));
        Frustum broken = f;
        broken.corners[5].x = INFINITY;
        expect_empty(intersection_body_cgal({broken, s, {0, 1, 0, 0}}, exact));
        // A flat frustum (all corners on one plane) sees nothing.
        Frustum flat = f;
        for (int i = 4; i < 8; ++i) flat.corners[i] = flat.corners[i - 4] + (f.corners[2] - f.corners[1]);
        expect_empty(intersection_body_cgal({flat, s, {0, 1, 0, 0}}, exact));
        // Point lights inside S: inside V (twice), at a corner of S outside V, at a corner of S that
        // is a vertex of V, and near S's face.
        const glm::dvec4 lights[] = {{0, 0, 0, 1}, {0, 0, 2.9, 1}, {3, 3, 3, 1}, {-3, -3, -3, 1}, {0.1, 2.5, -1, 1}};
        for (const glm::dvec4& light : lights) {
            SCOPED_TRACE(testing::Message()
                         << "light " << light.x << ' ' << light.y << ' ' << light.z << (exact ? " epeck" : " epick"));
            const BodyInput in{f, s, light};
            const IntersectionBody r = intersection_body_cgal(in, exact);
            expect_valid(r, in);
            // A light inside V leaves B = V.
            if (glm::dvec3(light) == glm::dvec3(0.0)) {
                EXPECT_NEAR(r.body.volume(), r.visible.volume(), 1e-9 * r.visible.volume());
            }
        }
        // Side planes through S's top edges and the far plane on S's bottom face: V = S.
        const Frustum exact_fit = make_frustum({0, 0, 6}, {0, 0, -1}, {0, 1, 0}, 90, 1.0, 1.0, 9.0);
        const BodyInput in{exact_fit, s, {1, 1, 1, 0}};
        const IntersectionBody r = intersection_body_cgal(in, exact);
        expect_valid(r, in);
        EXPECT_NEAR(r.visible.volume(), 216.0, 1e-9);
        EXPECT_NEAR(r.body.volume(), 216.0, 1e-9);
    }
}

TEST(BodyCgal, KernelsAgreeOnRandomConfigurations) {
    std::mt19937 rng(20240611);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    auto point_in = [&](const Aabb& b) {
        return glm::dvec3(uniform(b.min.x, b.max.x), uniform(b.min.y, b.max.y), uniform(b.min.z, b.max.z));
    };
    int non_empty = 0;
    const int runs = 40;
    for (int run = 0; run < runs; ++run) {
        const glm::dvec3 lo(uniform(-10, 10), uniform(-10, 10), uniform(-10, 10));
        const Aabb s = box(lo, lo + glm::dvec3(uniform(1, 20), uniform(0.2, 5), uniform(1, 20)));
        const Aabb around = box(s.min - 0.5 * s.extent(), s.max + 0.5 * s.extent());
        const glm::dvec3 eye = point_in(around);
        glm::dvec3 dir = point_in(s) - eye;
        if (glm::length(dir) < 1e-3) dir = {0, 0, -1};
        const Frustum f = make_frustum(eye, dir, {uniform(-0.3, 0.3), 1, uniform(-0.3, 0.3)}, uniform(20, 90),
                                       uniform(0.5, 2), uniform(0.1, 1), uniform(2, 40));
        const glm::dvec4 light = run % 2 ? glm::dvec4(point_in(around), 1.0)
                                         : glm::dvec4(uniform(-1, 1), uniform(0.1, 1), uniform(-1, 1), 0.0);
        SCOPED_TRACE(testing::Message() << "run " << run);
        non_empty += kernels_agree({f, s, light});
        if (testing::Test::HasFatalFailure()) return;
    }
    EXPECT_GE(non_empty, runs / 2);
}

// Grazing configurations: eye, view and light directions on an integer lattice around S, 90° fields
// of view (planes through S's edges, up to tan's rounding), far planes through S's farthest corner.
// Slivers thinner than double precision can orient must come out empty from both kernels.
TEST(BodyCgal, GrazingLatticeConfigurations) {
    const Aabb s = box({-2, -1, -3}, {2, 1, 3});
    std::mt19937 rng(7);
    auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
    int non_empty = 0;
    const int runs = 150;
    for (int run = 0; run < runs; ++run) {
        const glm::dvec3 eye(pick(9) - 4, pick(5) - 2, pick(11) - 5);
        glm::dvec3 dir(pick(3) - 1, pick(3) - 1, pick(3) - 1);
        if (dir == glm::dvec3(0.0)) dir = {0, 0, -1};
        const glm::dvec3 up = dir.x == 0 && dir.z == 0 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        const double near = pick(2) ? 1.0 : 0.5;
        double fit = 0.0;
        for (const glm::dvec3& c : s.corners()) fit = std::max(fit, glm::dot(c - eye, glm::normalize(dir)));
        const double far = run % 2 ? std::max(fit, near + 1.0) : double(pick(8) + 2);
        const Frustum f = make_frustum(eye, dir, up, pick(2) ? 90.0 : 60.0, pick(2) ? 1.0 : 2.0, near, far);
        const glm::dvec4 light = pick(2) ? glm::dvec4(pick(5) - 2, pick(3) - 1, pick(7) - 3, 1.0)
                                         : glm::dvec4(pick(3) - 1, pick(3) - 1, pick(3) - 1, 0.0);
        SCOPED_TRACE(testing::Message() << "run " << run);
        non_empty += kernels_agree({f, s, light});
        if (testing::Test::HasFatalFailure()) return;
    }
    EXPECT_GE(non_empty, runs / 3);
}

}  // namespace
}  // namespace shadowlab
