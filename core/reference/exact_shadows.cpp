// The visible point (the pixel's ray on the hit triangle's plane) and the normal are recomputed in
// double precision from the hit triangle.
// Embree works in float32: the tracer gets the scene in camera-relative coordinates (as
// large-world renderers rebase), so that a scene a million units from the origin is traced as
// precisely as one at the origin; everything else stays in world coordinates, in double.
#include "reference/exact_shadows.hpp"

#include "math/parallel_rows.hpp"
#include "reference/camera_rays.hpp"
#include "reference/light_samples.hpp"
#include "reference/ray_tracer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

namespace shadowlab {
namespace {

// Shadow rays leave the surface by this many float32 steps (ulps) of the largest coordinate of the
// point and its triangle, in camera-relative coordinates: the tracer's triangle, rounded to
// float32, lies within half an ulp of those coordinates of the exact one (Wächter and Binder, "A
// Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems, 2019: an offset sized
// by the local coordinates' floating-point precision, not by the scene's extent).
constexpr double kOffsetUlps = 64.0;

std::array<glm::dvec3, 3> corners(const WorldTriangles& triangles, int triangle) {
    const std::array<int, 3>& t = triangles.triangles[triangle];
    return {triangles.vertices[t[0]], triangles.vertices[t[1]], triangles.vertices[t[2]]};
}

double largest_coordinate(const glm::dvec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

// Where the pixel's ray meets the triangle's plane: exact in double, where Embree's float32
// barycentric weights would place the point off the pixel's ray.
glm::dvec3 on_plane(const std::array<glm::dvec3, 3>& triangle, const EyeRay& ray) {
    const glm::dvec3 normal = glm::cross(triangle[1] - triangle[0], triangle[2] - triangle[0]);
    return ray.origin + ray.direction * (glm::dot(normal, triangle[0] - ray.origin) / glm::dot(normal, ray.direction));
}

// kOffsetUlps float32 steps at the largest coordinate of p and the triangle (camera-relative).
double surface_offset(const std::array<glm::dvec3, 3>& triangle, const glm::dvec3& p) {
    double largest = largest_coordinate(p);
    for (const glm::dvec3& v : triangle) largest = std::max(largest, largest_coordinate(v));
    const float at = std::max(static_cast<float>(largest), std::numeric_limits<float>::min());
    return kOffsetUlps * static_cast<double>(std::nextafter(at, INFINITY) - at);
}

// Whether the surface point p of `triangle` sees the light past every caster; p, the triangle and
// the light in the tracer's camera-relative coordinates.
bool sees_light(const RayTracer& tracer, const Light& light, const std::array<glm::dvec3, 3>& triangle,
                const glm::dvec3& p) {
    const glm::dvec3 to_light = light.is_directional() ? -glm::normalize(light.direction) : light.position - p;
    glm::dvec3 normal = glm::normalize(glm::cross(triangle[1] - triangle[0], triangle[2] - triangle[0]));
    if (glm::dot(normal, to_light) < 0.0) normal = -normal;
    const glm::dvec3 origin = p + surface_offset(triangle, p) * normal;
    if (light.is_directional()) return !tracer.blocked(origin, to_light, std::numeric_limits<double>::infinity());
    return !tracer.blocked(origin, light.position - origin, 1.0);  // t = 1 at the light
}

// The unit normal of the triangle's side seen from `eye` (the point the camera sees p from).
glm::dvec3 seen_normal(const std::array<glm::dvec3, 3>& triangle, const glm::dvec3& p, const glm::dvec3& eye) {
    const glm::dvec3 normal = glm::normalize(glm::cross(triangle[1] - triangle[0], triangle[2] - triangle[0]));
    return glm::dot(normal, eye - p) < 0.0 ? -normal : normal;
}

// cos of the angle between the light and a normal at p.
double facing_light(const Light& light, const glm::dvec3& normal, const glm::dvec3& p) {
    const glm::dvec3 to_light = light.is_directional() ? -light.direction : light.position - p;
    return glm::dot(normal, glm::normalize(to_light));
}

// The share of the light the surface point p sees, from the stratified samples (seeded by the pixel).
double visible_share(const RayTracer& tracer, const Light& light, const std::array<glm::dvec3, 3>& triangle,
                     const glm::dvec3& p, int samples, std::uint32_t seed) {
    const glm::dvec3 to_centre = light.is_directional() ? -glm::normalize(light.direction) : light.position - p;
    glm::dvec3 normal = glm::normalize(glm::cross(triangle[1] - triangle[0], triangle[2] - triangle[0]));
    if (glm::dot(normal, to_centre) < 0.0) normal = -normal;
    const glm::dvec3 origin = p + surface_offset(triangle, p) * normal;
    const std::vector<glm::dvec2> disc = stratified_disc(samples, seed);
    int seen = 0;
    for (const glm::dvec2& s : disc)
        seen += light.is_directional()
                    ? !tracer.blocked(origin, sun_direction(light, s), std::numeric_limits<double>::infinity())
                    : !tracer.blocked(origin, sphere_light_point(light, p, s) - origin, 1.0);
    return double(seen) / double(disc.size());
}

enum class ShadowRays { traced, skipped, area };

ReferenceImage trace_camera(const Scene& scene, const WorldTriangles& triangles, int width, int height,
                            ShadowRays shadow_rays, int samples = 0) {
    const Camera& camera = scene.camera;
    const glm::dvec3 origin = camera.position;  // the tracer's: the camera's position at 0
    const WorldTriangles local = relative_to(triangles, origin);
    const RayTracer tracer(local, caster_flags(scene));
    Light local_light = scene.light;
    local_light.position -= origin;
    const CameraRays rays(camera, width, height);

    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    ReferenceImage image{width,
                         height,
                         std::vector<glm::dvec3>(pixels),
                         std::vector<int>(pixels, -1),
                         std::vector<uint8_t>(pixels, 0),
                         std::vector<uint8_t>(pixels, 0),
                         std::vector<float>(pixels, 0.0f),
                         std::vector<glm::dvec3>(pixels)};
    if (shadow_rays == ShadowRays::area) {
        image.visibility.assign(pixels, 0.0f);
        image.light_samples = int(stratified_disc(samples, 0).size());
    }
    auto trace_row = [&](int y) {
        for (int x = 0; x < width; ++x) {
            const EyeRay world_ray = rays.ray(x, y);
            const EyeRay ray{.origin = world_ray.origin - origin, .direction = world_ray.direction};
            const std::optional<Hit> hit = tracer.first_hit(ray.origin, ray.direction, camera.near, camera.far);
            if (!hit) continue;
            const std::array<glm::dvec3, 3> triangle = corners(triangles, hit->triangle);
            const std::array<glm::dvec3, 3> local_triangle = corners(local, hit->triangle);
            const glm::dvec3 local_p = on_plane(local_triangle, ray);
            const glm::dvec3 p = origin + local_p;
            const std::size_t i = static_cast<std::size_t>(y) * width + x;
            image.position[i] = p;
            image.object[i] = triangles.object[hit->triangle];
            image.visible[i] = 1;
            if (shadow_rays == ShadowRays::skipped) continue;
            image.lit[i] = sees_light(tracer, local_light, local_triangle, local_p);
            image.normal[i] = seen_normal(triangle, p, camera.eye_of(p));
            image.facing[i] = float(facing_light(scene.light, image.normal[i], p));
            if (shadow_rays == ShadowRays::area)
                image.visibility[i] =
                    float(visible_share(tracer, local_light, local_triangle, local_p, samples, std::uint32_t(i)));
        }
    };
    parallel_rows([&](int first, int stride) {
        for (int y = first; y < height; y += stride) trace_row(y);
    });
    return image;
}

}  // namespace

ReferenceImage exact_reference(const Scene& scene, const WorldTriangles& triangles, int width, int height) {
    return trace_camera(scene, triangles, width, height, ShadowRays::traced);
}

ReferenceImage soft_reference(const Scene& scene, const WorldTriangles& triangles, int width, int height, int samples) {
    return trace_camera(scene, triangles, width, height, ShadowRays::area, samples);
}

ReferenceImage light_reference(const Scene& scene, const WorldTriangles& triangles, int width, int height,
                               int light_samples) {
    return scene.light.is_area() ? soft_reference(scene, triangles, width, height, light_samples)
                                 : exact_reference(scene, triangles, width, height);
}

ReferenceImage visible_points(const Scene& scene, const WorldTriangles& triangles, int width, int height) {
    return trace_camera(scene, triangles, width, height, ShadowRays::skipped);
}

}  // namespace shadowlab
