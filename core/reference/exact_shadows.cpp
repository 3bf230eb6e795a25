// The visible point and the normal are recomputed in double precision from the hit triangle.
#include "reference/exact_shadows.hpp"

#include "math/parallel_rows.hpp"
#include "reference/camera_rays.hpp"
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

constexpr double kRelativeOffset = 1e-5;  // shadow-ray origin offset per unit of the scene's largest coordinate

double largest_coordinate(const std::vector<glm::dvec3>& vertices) {
    double largest = 0.0;
    for (const glm::dvec3& v : vertices) largest = std::max({largest, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    return largest;
}

std::array<glm::dvec3, 3> corners(const WorldTriangles& triangles, int triangle) {
    const std::array<int, 3>& t = triangles.triangles[triangle];
    return {triangles.vertices[t[0]], triangles.vertices[t[1]], triangles.vertices[t[2]]};
}

// Whether the surface point p of `triangle` sees the light past every caster.
bool sees_light(const RayTracer& tracer, const Light& light, const std::array<glm::dvec3, 3>& triangle,
                const glm::dvec3& p, double offset) {
    const glm::dvec3 to_light = light.is_directional() ? -glm::normalize(light.direction) : light.position - p;
    glm::dvec3 normal = glm::normalize(glm::cross(triangle[1] - triangle[0], triangle[2] - triangle[0]));
    if (glm::dot(normal, to_light) < 0.0) normal = -normal;
    const glm::dvec3 origin = p + offset * normal;
    if (light.is_directional()) return !tracer.blocked(origin, to_light, std::numeric_limits<double>::infinity());
    return !tracer.blocked(origin, light.position - origin, 1.0);  // t = 1 at the light
}

// cos of the angle between the light and the normal of the triangle's side seen from `eye`.
double facing_light(const Light& light, const std::array<glm::dvec3, 3>& triangle, const glm::dvec3& p,
                    const glm::dvec3& eye) {
    glm::dvec3 normal = glm::normalize(glm::cross(triangle[1] - triangle[0], triangle[2] - triangle[0]));
    if (glm::dot(normal, eye - p) < 0.0) normal = -normal;
    const glm::dvec3 to_light = light.is_directional() ? -light.direction : light.position - p;
    return glm::dot(normal, glm::normalize(to_light));
}

}  // namespace

ReferenceImage exact_reference(const Scene& scene, const WorldTriangles& triangles, int width, int height) {
    const RayTracer tracer(triangles, caster_flags(scene));
    const double offset = kRelativeOffset * largest_coordinate(triangles.vertices);
    const Camera& camera = scene.camera;
    const CameraRays rays(camera, width, height);

    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    ReferenceImage image{width, height, std::vector<glm::dvec3>(pixels), std::vector<int>(pixels, -1),
                         std::vector<uint8_t>(pixels, 0), std::vector<uint8_t>(pixels, 0),
                         std::vector<float>(pixels, 0.0f)};
    auto trace_row = [&](int y) {
        for (int x = 0; x < width; ++x) {
            const std::optional<Hit> hit = tracer.first_hit(camera.position, rays.direction(x, y), camera.near, camera.far);
            if (!hit) continue;
            const std::array<glm::dvec3, 3> triangle = corners(triangles, hit->triangle);
            const glm::dvec3 p = (1.0 - hit->u - hit->v) * triangle[0] + hit->u * triangle[1] + hit->v * triangle[2];
            const std::size_t i = static_cast<std::size_t>(y) * width + x;
            image.position[i] = p;
            image.object[i] = triangles.object[hit->triangle];
            image.visible[i] = 1;
            image.lit[i] = sees_light(tracer, scene.light, triangle, p, offset);
            image.facing[i] = float(facing_light(scene.light, triangle, p, camera.position));
        }
    };
    parallel_rows([&](int first, int stride) {
        for (int y = first; y < height; y += stride) trace_row(y);
    });
    return image;
}

}  // namespace shadowlab
