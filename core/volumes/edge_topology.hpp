#pragma once
// How one object's triangles share their edges: shadow volumes from silhouette edges need closed,
// consistently oriented meshes, so open and non-manifold edges are found and counted.
#include <array>
#include <string>
#include <vector>
#include <glm/glm.hpp>

#include "scene/scene.hpp"
#include "scene/tessellation.hpp"

namespace shadowlab {

// One use of an edge by a triangle: +1 when the triangle runs along it from `a` to `b`.
struct EdgeUse {
    int triangle;  // index in WorldTriangles
    int direction;
};

struct MeshEdge {
    glm::dvec3 a, b;  // its ends, in a fixed order (a < b lexicographically)
    std::vector<EdgeUse> uses;

    bool open() const { return uses.size() == 1; }
    // More than two triangles, or two running the same way (inconsistent winding).
    bool non_manifold() const {
        return uses.size() > 2 || (uses.size() == 2 && uses[0].direction == uses[1].direction);
    }
};

struct ObjectTopology {
    int object = -1;  // index in Scene::objects
    std::string name;
    std::vector<int> triangles;  // its triangles in WorldTriangles
    std::vector<MeshEdge> edges;
    int open_edges = 0, non_manifold_edges = 0;

    bool closed() const { return open_edges == 0 && non_manifold_edges == 0; }
};

// The edges of each casting object's triangles; vertices are joined by exact position, so a mesh
// whose file splits its corners still closes.
std::vector<ObjectTopology> caster_topology(const Scene& scene, const WorldTriangles& triangles);

}  // namespace shadowlab
