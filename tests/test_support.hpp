#pragma once
// Scenes and checks shared by the method tests.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <optional>

#include "lookup/shadow_reader.hpp"
#include "maps/map_lookup.hpp"
#include "registry/method.hpp"
#include "scene/scene.hpp"

namespace shadowlab::testing {

inline std::string source_path(const std::string& relative) {
    return (std::filesystem::path(SHADOWLAB_SOURCE_DIR) / relative).string();
}

// A square camera 20 units up, looking straight down at the origin (-z up the image), 60° high.
inline Camera camera_20_units_above_the_origin() {
    Camera camera;
    camera.position = {0, 20, 0};
    camera.target = {0, 0, 0};
    camera.up = {0, 0, -1};
    camera.fov_y_deg = 60;
    camera.aspect = 1;
    camera.near = 1;
    camera.far = 100;
    return camera;
}

inline std::vector<std::string> shipped_scenes() {
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(source_path("data/scenes")))
        if (entry.path().extension() == ".json") files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

// A ground plane and `count` boxes scattered over [-size/2, size/2]^2, heights up to size/5.
inline Scene random_town(int count, double size, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-0.5, 0.5), h(0.01, 0.2), w(0.005, 0.03);
    Scene scene;
    SceneObject ground;
    ground.shape = Shape::plane;
    ground.size = {size, 1.0, size};
    scene.objects.push_back(ground);
    for (int i = 0; i < count; ++i) {
        SceneObject box;
        box.size = {w(rng) * size, h(rng) * size, w(rng) * size};
        box.position = {u(rng) * size, box.size.y / 2, u(rng) * size};
        box.rotation_deg = {0.0, 360.0 * (u(rng) + 0.5), 0.0};
        scene.objects.push_back(box);
    }
    return scene;
}

inline bool finite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

inline bool in_unit_cube(const glm::dvec3& p, double tolerance) {
    return glm::all(glm::greaterThanEqual(p, glm::dvec3(-tolerance))) &&
           glm::all(glm::lessThanEqual(p, glm::dvec3(1.0 + tolerance)));
}

// Every note is a fallback (not a technique's limit) with particulars.
inline bool are_fallbacks(const std::vector<Note>& notes) {
    return std::all_of(notes.begin(), notes.end(), [](const Note& n) {
        return info(n.kind).category == NoteCategory::fallback && !n.message.empty();
    });
}

inline bool has_note(const std::vector<Note>& notes, NoteKind kind) {
    return std::any_of(notes.begin(), notes.end(), [&](const Note& n) { return n.kind == kind; });
}

// (u, v, d) of a world point under the map the setup picks for it (any number of maps).
// The share of a unit disc on the far side of the chord at u (u = -1: all of it, 1: none).
inline double disc_share_beyond(double u) {
    u = std::clamp(u, -1.0, 1.0);
    return (std::acos(u) - u * std::sqrt(1.0 - u * u)) / std::numbers::pi;
}

// A sphere light of radius 0.25 (w_light = 0.5) at height 5 over the ground, a thin blocker at
// height 3 covering x < 0 (d_b = 2, d_r = 5), seen straight down from height 1 in a strip across
// the edge.
inline Scene edge_under_a_sphere_light() {
    Scene scene;
    scene.objects.push_back({.name = "ground", .shape = Shape::plane, .size = {40.0, 1.0, 40.0}, .casts = false});
    scene.objects.push_back({.name = "blocker",
                             .shape = Shape::plane,
                             .position = {-10.0, 3.0, 0.0},
                             .size = {20.0, 1.0, 40.0},
                             .receives = false});
    scene.light = {.type = LightType::point, .position = {0.0, 5.0, 0.0}, .radius = 0.25};
    scene.camera = {.position = {0.0, 1.0, 0.0},
                    .target = {0.0, 0.0, 0.0},
                    .up = {0.0, 0.0, -1.0},
                    .fov_y_deg = 7.0,
                    .aspect = 10.0,
                    .near = 0.1,
                    .far = 10.0};
    return scene;
}

// VSM's light bleeding case: an 8 x 8 ground under a low caster that shadows all of it, and a high
// one (nearer the light) over x < 0, seen from between the ground and the low caster. A filter
// region holding both casters has a wide variance with a mean between them, and Chebyshev's bound
// lights the ground there although the low caster shadows it fully.
inline Scene ground_under_a_low_and_a_high_caster() {
    Scene scene;
    scene.objects.push_back({.name = "ground", .shape = Shape::plane, .size = {8.0, 1.0, 8.0}, .casts = false});
    scene.objects.push_back({.name = "low",
                             .shape = Shape::plane,
                             .position = {0.0, 0.5, 0.0},
                             .size = {8.0, 1.0, 8.0},
                             .receives = false});
    scene.objects.push_back({.name = "high",
                             .shape = Shape::plane,
                             .position = {-2.0, 6.0, 0.0},
                             .size = {4.0, 1.0, 8.0},
                             .receives = false});
    scene.light = {.direction = {0, -1, 0}, .angular_radius_deg = 0.5};
    scene.camera = {.position = {0, 0.3, 0.001},
                    .target = {0, 0, 0},
                    .up = {0, 0, -1},
                    .fov_y_deg = 90,
                    .aspect = 1,
                    .near = 0.05,
                    .far = 2};
    return scene;
}

// The hard lookup of point p with a constant bias (world units along the light) and no other:
// visibility 0..1 (a blend band crossfades two maps). The light only orients the bias: straight
// down by default.
inline double constant_bias_visibility(const DepthMap& depth, const ShadowSetup& setup, const glm::dvec3& p,
                                       double bias, const Light& light = Light{.direction = {0, -1, 0}}) {
    const ShadowReader reader(setup, depth, light, {.bias = {.constant = bias, .slope_scale = 0.0}});
    return reader.visibility({.position = p, .normal = -light.direction});
}
inline bool in_shadow(const DepthMap& depth, const ShadowSetup& setup, const glm::dvec3& p, double bias,
                      const Light& light = Light{.direction = {0, -1, 0}}) {
    return constant_bias_visibility(depth, setup, p, bias, light) < 0.5;
}

inline std::optional<glm::dvec3> setup_uvz(const ShadowSetup& setup, const glm::dvec3& p) {
    const std::optional<MapPoint> at = map_point(setup, p);
    if (!at) return std::nullopt;
    return at->uvz();
}

// The registry's shadow-map methods (the geometric techniques have no maps).
inline std::vector<const Method*> map_methods() {
    std::vector<const Method*> out;
    for (const Method& m : all_methods())
        if (m.makes_maps()) out.push_back(&m);
    return out;
}

}  // namespace shadowlab::testing

namespace shadowlab::testing {

// Does the ray from p toward the light (against `direction`, the way light travels) meet the box?
inline bool ray_to_light_hits(const glm::dvec3& p, const glm::dvec3& direction, const Aabb& box) {
    double t0 = 0.0, t1 = INFINITY;
    for (int a = 0; a < 3; ++a) {
        const double d = -direction[a];
        if (std::abs(d) < 1e-15) {
            if (p[a] < box.min[a] || p[a] > box.max[a]) return false;
            continue;
        }
        double ta = (box.min[a] - p[a]) / d, tb = (box.max[a] - p[a]) / d;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    return t0 <= t1;
}

// Visible points a caster can shadow (directional light): corners, face centres and centres of
// the receiver boxes, inside the frustum, whose ray toward the light meets a caster box.
inline std::vector<glm::dvec3> shadowable_visible_points(const ShadowInputs& in) {
    std::vector<glm::dvec3> out;
    const double tol = 1e-7 * in.scene_bounds.diagonal();
    for (const Aabb& r : in.receivers) {
        const auto corners = r.corners();
        std::vector<glm::dvec3> samples(corners.begin(), corners.end());
        samples.push_back(r.center());
        for (int a = 0; a < 3; ++a)
            for (double side : {r.min[a], r.max[a]}) {
                glm::dvec3 c = r.center();
                c[a] = side;
                samples.push_back(c);
            }
        for (const glm::dvec3& p : samples) {
            if (!in.frustum.contains(p, -tol)) continue;
            for (const Aabb& c : in.casters)
                if (ray_to_light_hits(p, in.light.direction, c)) {
                    out.push_back(p);
                    break;
                }
        }
    }
    return out;
}

}  // namespace shadowlab::testing
