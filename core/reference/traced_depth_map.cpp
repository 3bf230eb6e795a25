#include "reference/traced_depth_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "maps/map_lookup.hpp"
#include "math/parallel_rows.hpp"
#include "raster/paraboloid_edges.hpp"
#include "reference/ray_tracer.hpp"

namespace shadowlab {
namespace {

// The casters alone (the tracer's nearest hit meets every triangle it holds), relative to `origin`.
WorldTriangles casters_relative_to(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object,
                                   const glm::dvec3& origin) {
    WorldTriangles out;
    for (const glm::dvec3& v : triangles.vertices) out.vertices.push_back(v - origin);
    for (std::size_t i = 0; i < triangles.triangles.size(); ++i)
        if (casts_per_object.at(triangles.object[i])) {
            out.triangles.push_back(triangles.triangles[i]);
            out.object.push_back(triangles.object[i]);
            if (triangles.alpha_tested()) out.alpha.push_back(triangles.alpha[i]);
        }
    return out;
}

// How far the ray from the origin along the unit `direction` runs to the triangle's plane: in double,
// where Embree's float32 barycentric weights would place the hit off the texel's ray.
double distance_to_plane(const WorldTriangles& local, int triangle, const glm::dvec3& direction) {
    const std::array<int, 3>& t = local.triangles[triangle];
    const glm::dvec3 &a = local.vertices[t[0]], &b = local.vertices[t[1]], &c = local.vertices[t[2]];
    const glm::dvec3 normal = glm::cross(b - a, c - a);
    return glm::dot(normal, a) / glm::dot(normal, direction);
}

// The map's (u, v) at the centre of texel (x, y) of the texture: texture_uv taken back.
glm::dvec2 map_uv_of_texel(const ShadowMap& map, int x, int y, int resolution) {
    const glm::dvec2 texture = (glm::dvec2(x, y) + 0.5) / double(resolution);
    const glm::dvec2 lo(map.viewport.x, map.viewport.y), hi(map.viewport.z, map.viewport.w);
    return (texture - lo) / (hi - lo);
}

void trace_paraboloid(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object, const ShadowMap& map,
                      DepthMap& out) {
    const Paraboloid& p = map.paraboloid;
    const WorldTriangles local = casters_relative_to(triangles, casts_per_object, p.centre);
    const RayTracer tracer(local, casts_per_object);
    const glm::dmat3 world_from_frame = glm::transpose(p.frame_from_world);  // a rotation
    const glm::ivec2 first = texel_of(map, glm::dvec2(0.0), out.resolution);
    const glm::ivec2 last = texel_of(map, glm::dvec2(1.0), out.resolution);
    const auto trace_row = [&](int y) {
        for (int x = first.x; x <= last.x; ++x) {
            const glm::dvec2 disc = 2.0 * map_uv_of_texel(map, x, y, out.resolution) - 1.0;
            if (glm::dot(disc, disc) > 1.0) continue;                            // outside the hemisphere's disc
            const glm::dvec3 direction = world_from_frame * direction_of(disc);  // unit: t is the distance
            const std::optional<Hit> hit = tracer.first_hit(glm::dvec3(0.0), direction, 0.0, INFINITY);
            if (!hit) continue;
            const double depth = (distance_to_plane(local, hit->triangle, direction) - p.near) / (p.far - p.near);
            out.set(x, y, std::clamp(depth, 0.0, 1.0));
        }
    };
    parallel_rows([&](int offset, int stride) {
        for (int y = first.y + offset; y <= last.y; y += stride) trace_row(y);
    });
}

}  // namespace

DepthMap traced_depth_map(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object,
                          const ShadowSetup& setup, int resolution) {
    DepthMap out(resolution, DepthFormat{});
    for (const ShadowMap& map : setup.maps) {
        if (map.projection != Projection::paraboloid)
            throw std::invalid_argument(std::string("traced_depth_map: a ") + to_string(map.projection) +
                                        " map; only paraboloid maps are traced");
        trace_paraboloid(triangles, casts_per_object, map, out);
    }
    return out;
}

}  // namespace shadowlab
