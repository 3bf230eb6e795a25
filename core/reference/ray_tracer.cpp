#include "reference/ray_tracer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <embree3/rtcore.h>

#include "io/value_text.hpp"

namespace shadowlab {
namespace {

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

// Embree's intersection and occlusion filter for alpha-tested casters: a hit where the triangle's
// texture alpha (at the hit's barycentric weights u, v of its second and third corners) is below its
// cutoff is refused, and the ray goes on to the next hit. The geometry's user data is its primitives'
// alpha tests.
void alpha_filter(const RTCFilterFunctionNArguments* args) {
    const auto& alpha = *static_cast<const std::vector<TriangleAlpha>*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const TriangleAlpha& triangle = alpha[RTCHitN_primID(args->hit, args->N, i)];
        if (!triangle.keeps(RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i))) args->valid[i] = 0;
    }
}

// The chosen triangles' alpha tests, primitive i's at i; empty when none of them is alpha-tested.
std::vector<TriangleAlpha> chosen_alpha(const WorldTriangles& triangles, const std::vector<int>& chosen) {
    if (!triangles.alpha_tested()) return {};
    std::vector<TriangleAlpha> out;
    for (int i : chosen) out.push_back(triangles.alpha[i]);
    if (std::none_of(out.begin(), out.end(), [](const TriangleAlpha& a) { return a.test != nullptr; })) return {};
    return out;
}

// A committed scene holding the chosen triangles; primitive i is chosen[i]. With alpha tests (`alpha`,
// which must outlive the scene) its hits pass alpha_filter.
ScenePtr build_scene(RTCDevice device, const WorldTriangles& triangles, const std::vector<int>& chosen,
                     const std::vector<TriangleAlpha>& alpha) {
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
        if (!alpha.empty()) {
            rtcSetGeometryUserData(geometry, const_cast<std::vector<TriangleAlpha>*>(&alpha));
            rtcSetGeometryIntersectFilterFunction(geometry, alpha_filter);
            rtcSetGeometryOccludedFilterFunction(geometry, alpha_filter);
        }
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

// Embree asserts (ray.valid(), an abort) on a ray whose origin or direction has a component beyond
// FLT_LARGE (1.8e18) or whose tnear or tfar is NaN. The origin must keep clear of that bound after
// rounding to float; the direction is rescaled below, so only its finiteness matters.
constexpr double kLargestOrigin = 1e18;

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
// Of a finite vector (std::max passes a NaN over).
double largest_magnitude(const glm::dvec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

// Throws std::invalid_argument naming what is wrong with the ray, instead of handing it to Embree.
void check_ray(const glm::dvec3& origin, const glm::dvec3& direction, double t_min, double t_max) {
    const auto refuse = [](const std::string& problem) { throw std::invalid_argument("invalid ray: " + problem); };
    if (!finite(origin) || largest_magnitude(origin) > kLargestOrigin)
        refuse("origin " + value_text(origin) + " is not finite or beyond ±1e18, the tracer's float range");
    if (!finite(direction)) refuse("direction " + value_text(direction) + " is not finite");
    if (largest_magnitude(direction) == 0.0) refuse("direction is zero");
    if (!(std::isfinite(t_min) && t_min >= 0.0 && t_max >= t_min))
        refuse("t range " + value_text(glm::dvec2(t_min, t_max)) + " is not a finite start >= 0 and an end >= start");
}

// The direction divided by its largest |component| (t multiplied by it, so the same points are
// meant): any finite non-zero direction then fits Embree's float range.
RTCRay make_ray(const glm::dvec3& origin, const glm::dvec3& direction, double t_min, double t_max) {
    check_ray(origin, direction, t_min, t_max);
    const double scale = largest_magnitude(direction);
    const glm::dvec3 unit_direction = direction / scale;
    RTCRay ray{};
    ray.org_x = static_cast<float>(origin.x);
    ray.org_y = static_cast<float>(origin.y);
    ray.org_z = static_cast<float>(origin.z);
    ray.dir_x = static_cast<float>(unit_direction.x);
    ray.dir_y = static_cast<float>(unit_direction.y);
    ray.dir_z = static_cast<float>(unit_direction.z);
    ray.tnear = static_cast<float>(t_min * scale);
    ray.tfar = static_cast<float>(t_max * scale);
    ray.mask = ~0u;  // this Embree build tests ray masks: a zero mask would meet nothing
    return ray;
}

}  // namespace

struct RayTracer::Bvhs {
    // Each BVH's primitives' alpha tests, which its filter reads (declared before the BVHs: they are
    // released after them).
    std::vector<TriangleAlpha> all_alpha, casters_alpha;
    DevicePtr device;
    ScenePtr all{nullptr, &rtcReleaseScene}, casters{nullptr, &rtcReleaseScene};
};

RayTracer::RayTracer(const WorldTriangles& triangles, const std::vector<bool>& casts) {
    const std::vector<int> all = triangles_where(triangles, [](int) { return true; });
    const std::vector<int> casters = triangles_where(triangles, [&](int object) { return bool(casts.at(object)); });
    bvhs_.reset(new Bvhs{.all_alpha = chosen_alpha(triangles, all),
                         .casters_alpha = chosen_alpha(triangles, casters),
                         .device = new_device()});
    bvhs_->all = build_scene(bvhs_->device.get(), triangles, all, bvhs_->all_alpha);
    bvhs_->casters = build_scene(bvhs_->device.get(), triangles, casters, bvhs_->casters_alpha);
}

RayTracer::~RayTracer() = default;

std::optional<Hit> RayTracer::first_hit(const glm::dvec3& origin, const glm::dvec3& direction, double t_min,
                                        double t_max) const {
    RTCRayHit query{};
    query.ray = make_ray(origin, direction, t_min, t_max);
    query.hit.geomID = query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcIntersect1(bvhs_->all.get(), &context, &query);
    if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    return Hit{static_cast<int>(query.hit.primID), query.hit.u, query.hit.v};
}

bool RayTracer::blocked(const glm::dvec3& origin, const glm::dvec3& direction, double t_max) const {
    RTCRay ray = make_ray(origin, direction, 0.0, t_max);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcOccluded1(bvhs_->casters.get(), &context, &ray);
    return ray.tfar < 0.0f;  // Embree marks an occluded ray with tfar = -inf
}

}  // namespace shadowlab
