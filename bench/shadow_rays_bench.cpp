// The same shadow rays (from every visible pixel of the default scene toward the sun) traced by
// Embree and by CGAL's AABB tree, on one thread, BVH builds outside the timing.
#include <benchmark/benchmark.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "reference/exact_shadows.hpp"
#include "reference/ray_tracer.hpp"
#include "scene/scene_loader.hpp"

using namespace shadowlab;

namespace {

struct ShadowRays {
    WorldTriangles triangles;
    std::vector<bool> casts;
    std::vector<glm::dvec3> origins;
    glm::dvec3 to_light;
};

// Rays from the visible points of a 640x360 view, lifted a little toward the light.
const ShadowRays& default_scene_rays() {
    static const ShadowRays rays = [] {
        const Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/default.json");
        ShadowRays r{tessellate(scene), caster_flags(scene), {}, -scene.light.direction};
        const ReferenceImage image = exact_reference(scene, r.triangles, 640, 360);
        for (size_t i = 0; i < image.position.size(); ++i)
            if (image.visible[i]) r.origins.push_back(image.position[i] + 1e-3 * r.to_light);
        return r;
    }();
    return rays;
}

void embree(benchmark::State& state) {
    const ShadowRays& rays = default_scene_rays();
    const RayTracer tracer(rays.triangles, rays.casts);
    for (auto _ : state) {
        size_t blocked = 0;
        for (const glm::dvec3& o : rays.origins) blocked += tracer.blocked(o, rays.to_light, INFINITY);
        benchmark::DoNotOptimize(blocked);
    }
    state.SetItemsProcessed(int64_t(state.iterations() * rays.origins.size()));
}

void cgal_aabb_tree(benchmark::State& state) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Triangles = std::vector<K::Triangle_3>;
    using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>>>;
    const ShadowRays& rays = default_scene_rays();
    Triangles casters;
    auto point = [&](int v) {
        const glm::dvec3& p = rays.triangles.vertices[v];
        return K::Point_3(p.x, p.y, p.z);
    };
    for (size_t t = 0; t < rays.triangles.triangles.size(); ++t)
        if (rays.casts[rays.triangles.object[t]]) {
            const auto& tri = rays.triangles.triangles[t];
            casters.emplace_back(point(tri[0]), point(tri[1]), point(tri[2]));
        }
    Tree tree(casters.begin(), casters.end());
    tree.accelerate_distance_queries();
    const K::Vector_3 direction(rays.to_light.x, rays.to_light.y, rays.to_light.z);
    for (auto _ : state) {
        size_t blocked = 0;
        for (const glm::dvec3& o : rays.origins)
            blocked += tree.do_intersect(K::Ray_3(K::Point_3(o.x, o.y, o.z), direction));
        benchmark::DoNotOptimize(blocked);
    }
    state.SetItemsProcessed(int64_t(state.iterations() * rays.origins.size()));
}

}  // namespace

BENCHMARK(embree)->Unit(benchmark::kMillisecond);
BENCHMARK(cgal_aabb_tree)->Unit(benchmark::kMillisecond);
