#include "volumes/edge_topology.hpp"

#include <map>
#include <tuple>
#include <utility>

namespace shadowlab {
namespace {

using Key = std::tuple<double, double, double>;

Key key_of(const glm::dvec3& p) { return {p.x, p.y, p.z}; }

ObjectTopology topology_of(const Scene& scene, const WorldTriangles& triangles, int object,
                           const std::vector<int>& members) {
    ObjectTopology t{object, scene.objects[object].name, members, {}, 0, 0};
    std::map<std::pair<Key, Key>, std::size_t> index;  // (a, b) with a < b -> edge
    for (int triangle : members)
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3& p = triangles.vertices[triangles.triangles[triangle][k]];
            const glm::dvec3& q = triangles.vertices[triangles.triangles[triangle][(k + 1) % 3]];
            const bool forward = key_of(p) < key_of(q);
            const auto [it, added] =
                index.try_emplace({key_of(forward ? p : q), key_of(forward ? q : p)}, t.edges.size());
            if (added) t.edges.push_back({forward ? p : q, forward ? q : p, {}});
            t.edges[it->second].uses.push_back({triangle, forward ? 1 : -1});
        }
    for (const MeshEdge& e : t.edges) {
        t.open_edges += e.open();
        t.non_manifold_edges += e.non_manifold();
    }
    return t;
}

}  // namespace

std::vector<ObjectTopology> caster_topology(const Scene& scene, const WorldTriangles& triangles) {
    std::vector<std::vector<int>> members(scene.objects.size());
    for (std::size_t i = 0; i < triangles.triangles.size(); ++i)
        if (scene.objects[triangles.object[i]].casts) members[triangles.object[i]].push_back(int(i));
    std::vector<ObjectTopology> out;
    for (std::size_t o = 0; o < members.size(); ++o)
        if (!members[o].empty()) out.push_back(topology_of(scene, triangles, int(o), members[o]));
    return out;
}

}  // namespace shadowlab
