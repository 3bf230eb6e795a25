// Embree 3 traces the rays (in single precision) through two BVHs built per call: one over every
// triangle for the primary rays, one over the casters' triangles for the shadow rays. The visible
// point and the normal are recomputed in double precision from the hit triangle.
#include "reference/exact_shadows.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <embree3/rtcore.h>

namespace shadowlab {
namespace {

constexpr double kRelativeOffset = 1e-5;  // shadow-ray origin offset per unit of the scene's largest coordinate

using DevicePtr = std::unique_ptr<RTCDeviceTy, decltype(&rtcReleaseDevice)>;
using ScenePtr = std::unique_ptr<RTCSceneTy, decltype(&rtcReleaseScene)>;

void throw_if_error(RTCDevice device, const std::string& what) {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE)
        throw std::runtime_error("Embree: " + what + " failed (RTCError " + std::to_string(error) + ")");
}

// One build thread: the BVH, hence which of two coincident triangles a ray meets, is the same on
// every run.
DevicePtr new_device() {
    DevicePtr device(rtcNewDevice("threads=1"), &rtcReleaseDevice);
    if (!device) throw_if_error(nullptr, "creating a device");
    return device;
}

// A committed scene holding the chosen triangles; primitive i is chosen[i].
ScenePtr build_scene(RTCDevice device, const WorldTriangles& triangles, const std::vector<int>& chosen) {
    ScenePtr scene(rtcNewScene(device), &rtcReleaseScene);
    rtcSetSceneFlags(scene.get(), RTC_SCENE_FLAG_ROBUST);  // watertight triangle tests, robust traversal
    if (!chosen.empty()) {
        RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), triangles.vertices.size()));
        for (std::size_t i = 0; i < triangles.vertices.size(); ++i)
            for (int k = 0; k < 3; ++k) vertices[3 * i + k] = static_cast<float>(triangles.vertices[i][k]);
        auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), chosen.size()));
        for (std::size_t i = 0; i < chosen.size(); ++i)
            for (int k = 0; k < 3; ++k) indices[3 * i + k] = static_cast<unsigned>(triangles.triangles[chosen[i]][k]);
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(scene.get(), geometry);
        rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(scene.get());
    throw_if_error(device, "building a BVH");
    return scene;
}

// Indices of the triangles whose object passes `keep`.
template <class Predicate>
std::vector<int> triangles_where(const WorldTriangles& triangles, Predicate keep) {
    std::vector<int> out;
    for (std::size_t i = 0; i < triangles.triangles.size(); ++i)
        if (keep(triangles.object[i])) out.push_back(static_cast<int>(i));
    return out;
}

RTCRay make_ray(const glm::dvec3& origin, const glm::dvec3& direction, double t_min, double t_max) {
    RTCRay ray{};
    ray.org_x = static_cast<float>(origin.x);
    ray.org_y = static_cast<float>(origin.y);
    ray.org_z = static_cast<float>(origin.z);
    ray.dir_x = static_cast<float>(direction.x);
    ray.dir_y = static_cast<float>(direction.y);
    ray.dir_z = static_cast<float>(direction.z);
    ray.tnear = static_cast<float>(t_min);
    ray.tfar = static_cast<float>(t_max);
    ray.mask = ~0u;  // this Embree build tests ray masks: a zero mask would meet nothing
    return ray;
}

// A hit: the triangle and the barycentric weights of its second and third vertices.
struct Hit {
    int triangle;
    double u, v;
};

class Tracer {
public:
    Tracer(const WorldTriangles& triangles, const std::vector<bool>& casts)
        : device_(new_device()),
          all_(build_scene(device_.get(), triangles, triangles_where(triangles, [](int) { return true; }))),
          casters_(build_scene(device_.get(), triangles,
                               triangles_where(triangles, [&](int object) { return bool(casts.at(object)); }))) {}

    // The nearest triangle along origin + t direction, t in [t_min, t_max].
    std::optional<Hit> first_hit(const glm::dvec3& origin, const glm::dvec3& direction, double t_min,
                                 double t_max) const {
        RTCRayHit query{};
        query.ray = make_ray(origin, direction, t_min, t_max);
        query.hit.geomID = query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        rtcIntersect1(all_.get(), &context, &query);
        if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
        return Hit{static_cast<int>(query.hit.primID), query.hit.u, query.hit.v};
    }

    // Does a caster triangle meet origin + t direction, t in [0, t_max]?
    bool blocked(const glm::dvec3& origin, const glm::dvec3& direction, double t_max) const {
        RTCRay ray = make_ray(origin, direction, 0.0, t_max);
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        rtcOccluded1(casters_.get(), &context, &ray);
        return ray.tfar < 0.0f;  // Embree marks an occluded ray with tfar = -inf
    }

private:
    DevicePtr device_;
    ScenePtr all_, casters_;
};

double largest_coordinate(const std::vector<glm::dvec3>& vertices) {
    double largest = 0.0;
    for (const glm::dvec3& v : vertices) largest = std::max({largest, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    return largest;
}

std::array<glm::dvec3, 3> corners(const WorldTriangles& triangles, int triangle) {
    const std::array<int, 3>& t = triangles.triangles[triangle];
    return {triangles.vertices[t[0]], triangles.vertices[t[1]], triangles.vertices[t[2]]};
}

// The view-space direction through a pixel centre (row 0 at the top) of a symmetric perspective
// projection, scaled to z = -1 so that a ray's t along it is the view depth.
glm::dvec3 pixel_direction(const glm::dmat4& projection, int x, int y, int width, int height) {
    const double ndc_x = 2.0 * (x + 0.5) / width - 1.0, ndc_y = 1.0 - 2.0 * (y + 0.5) / height;
    return {ndc_x / projection[0][0], ndc_y / projection[1][1], -1.0};
}

// Whether the surface point p of `triangle` sees the light past every caster.
bool sees_light(const Tracer& tracer, const Light& light, const std::array<glm::dvec3, 3>& triangle,
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
    const Tracer tracer(triangles, caster_flags(scene));
    const double offset = kRelativeOffset * largest_coordinate(triangles.vertices);
    const Camera& camera = scene.camera;
    const glm::dmat4 projection = camera.projection_matrix();
    const glm::dmat3 view_to_world(glm::inverse(camera.view_matrix()));  // a rotation: t stays the view depth

    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    ReferenceImage image{width, height, std::vector<glm::dvec3>(pixels), std::vector<int>(pixels, -1),
                         std::vector<uint8_t>(pixels, 0), std::vector<uint8_t>(pixels, 0),
                         std::vector<float>(pixels, 0.0f)};
    auto trace_row = [&](int y) {
        for (int x = 0; x < width; ++x) {
            const glm::dvec3 direction = view_to_world * pixel_direction(projection, x, y, width, height);
            const std::optional<Hit> hit = tracer.first_hit(camera.position, direction, camera.near, camera.far);
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
    // Rows interleaved over the cores: each pixel is independent, so the image does not depend on
    // how many threads traced it.
    const int threads = int(std::max(1u, std::thread::hardware_concurrency()));
    std::vector<std::thread> workers;
    for (int t = 0; t < threads; ++t)
        workers.emplace_back([&, t] {
            for (int y = t; y < height; y += threads) trace_row(y);
        });
    for (std::thread& w : workers) w.join();
    return image;
}

}  // namespace shadowlab
