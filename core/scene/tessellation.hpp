#pragma once
// A scene as one triangle soup in world space, for the depth rasterizer and the ray-traced reference.
#include <array>
#include <vector>
#include <glm/glm.hpp>

#include "scene/alpha_test.hpp"
#include "scene/base_colour.hpp"
#include "scene/scene.hpp"

namespace shadowlab {

struct WorldTriangles {
    std::vector<glm::dvec3> vertices;
    std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from outside
    std::vector<int> object;                    // per triangle: its index in Scene::objects
    // Per triangle, its alpha test (scene/alpha_test.hpp: null for an opaque one); empty when no
    // triangle is alpha-tested, so that every reader's opaque path stays as it was.
    std::vector<TriangleAlpha> alpha;
    // Per triangle, its material's base colour (scene/base_colour.hpp), which the Camera view shows; empty
    // when no object has one (every triangle then in its object's palette colour).
    std::vector<TriangleColour> colour;

    bool alpha_tested() const { return !alpha.empty(); }
    bool coloured() const { return !colour.empty(); }
};

// Every object through its model_matrix(): a box gives 12 triangles, a plane 2 (facing +y), a
// sphere a UV sphere of `segments` slices and segments / 2 stacks, a cylinder `segments` side
// quads and two fan caps, a mesh its own triangles (as wound in its file), each with its material's
// alpha test and base colour where the object has them (SceneObject::material_alpha, material_colour)
// and, for a texture, the file gave its texture coordinates.
WorldTriangles tessellate(const Scene& scene, int segments = 24);

// The triangles with every vertex moved by -origin: relative to a light or the eye, as float32
// consumers (Embree, the GPU) need them far from the world's origin.
WorldTriangles relative_to(WorldTriangles triangles, const glm::dvec3& origin);

// Per object: does it cast shadows (SceneObject::casts)? Indexed like WorldTriangles::object.
std::vector<bool> caster_flags(const Scene& scene);

}  // namespace shadowlab
