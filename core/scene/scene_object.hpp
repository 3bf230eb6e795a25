#pragma once
// One object of a scene: a primitive or a mesh, placed by position, rotation and scale.
#include <memory>
#include <string>
#include <vector>
#include <glm/glm.hpp>

#include "geometry/aabb.hpp"
#include "scene/alpha_test.hpp"
#include "scene/base_colour.hpp"
#include "scene/triangle_mesh.hpp"

namespace shadowlab {

enum class Shape { box, sphere, plane, cylinder, mesh };

const char* to_string(Shape shape);

struct SceneObject {
    std::string name;
    Shape shape = Shape::box;
    glm::dvec3 position{0.0};
    glm::dvec3 rotation_deg{0.0};  // applied about x, then y, then z
    glm::dvec3 scale{1.0};
    glm::dvec3 size{1.0};   // box: full extents; plane: x and z extents (y unused)
    double radius = 0.5;    // sphere, cylinder
    double height = 1.0;    // cylinder (along local y)
    std::string mesh_file;  // mesh: path as written in the scene
    std::shared_ptr<const TriangleMesh> mesh;
    // Per material of its mesh file (TriangleSurface::material): an alpha-tested material's test, null
    // for an opaque one; empty when every material is opaque.
    std::vector<std::shared_ptr<const AlphaTest>> material_alpha;
    // Per material of its mesh file: its base colour, which the Camera view shows in place of the
    // object's palette colour; null for a material without one; empty when no material has one.
    std::vector<std::shared_ptr<const BaseColour>> material_colour;
    bool casts = true;
    bool receives = true;

    glm::dmat4 model_matrix() const;  // local -> world: T * Rz * Ry * Rx * S
    Aabb local_bounds() const;        // a plane is flat: zero extent in y
    Aabb world_bounds() const;
    // Whether a world point lies inside the solid: exact for the primitives, by the parity of a
    // ray's crossings for a mesh (closed meshes); a plane has no inside.
    bool contains(const glm::dvec3& world) const;
};

}  // namespace shadowlab
