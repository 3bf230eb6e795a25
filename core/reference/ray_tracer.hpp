#pragma once
// Rays against a scene's triangles with Embree 3 (single precision), Embree kept out of the header:
// one BVH over every triangle for the nearest hit, one over the casters' for occlusion. An
// alpha-tested triangle (WorldTriangles::alpha) is not there where its alpha is below its cutoff:
// Embree's intersection and occlusion filters pass such hits over, for both kinds of ray.
#include <memory>
#include <optional>
#include <vector>
#include <glm/glm.hpp>

#include "scene/tessellation.hpp"

namespace shadowlab {

// A hit: the triangle and the barycentric weights of its second and third vertices.
struct Hit {
    int triangle;
    double u, v;
};

class RayTracer {
public:
    // `casts` per object (see caster_flags): which triangles block shadow rays.
    RayTracer(const WorldTriangles& triangles, const std::vector<bool>& casts);
    ~RayTracer();
    RayTracer(const RayTracer&) = delete;
    RayTracer& operator=(const RayTracer&) = delete;

    // The nearest triangle along origin + t direction, t in [t_min, t_max]. Thread-safe.
    // A ray Embree cannot trace (an origin not finite or beyond ±1e18, a direction not finite or
    // zero, t_min not finite and >= 0, t_max below t_min or NaN) throws std::invalid_argument
    // naming what is wrong; a direction of any finite size is fine.
    std::optional<Hit> first_hit(const glm::dvec3& origin, const glm::dvec3& direction, double t_min,
                                 double t_max) const;
    // Does a caster triangle meet origin + t direction, t in [0, t_max]? Thread-safe; throws as
    // first_hit does.
    bool blocked(const glm::dvec3& origin, const glm::dvec3& direction, double t_max) const;

private:
    struct Bvhs;
    std::unique_ptr<Bvhs> bvhs_;
};

}  // namespace shadowlab
