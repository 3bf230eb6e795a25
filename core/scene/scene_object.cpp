#include "scene/scene_object.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab {

const char* to_string(Shape shape) {
    switch (shape) {
        case Shape::box: return "box";
        case Shape::sphere: return "sphere";
        case Shape::plane: return "plane";
        case Shape::cylinder: return "cylinder";
        case Shape::mesh: return "mesh";
    }
    return "unknown";
}

glm::dmat4 SceneObject::model_matrix() const {
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), position);
    m = glm::rotate(m, glm::radians(rotation_deg.z), glm::dvec3(0.0, 0.0, 1.0));
    m = glm::rotate(m, glm::radians(rotation_deg.y), glm::dvec3(0.0, 1.0, 0.0));
    m = glm::rotate(m, glm::radians(rotation_deg.x), glm::dvec3(1.0, 0.0, 0.0));
    return glm::scale(m, scale);
}

Aabb SceneObject::local_bounds() const {
    glm::dvec3 half;
    switch (shape) {
        case Shape::box: half = size / 2.0; break;
        case Shape::sphere: half = glm::dvec3(radius); break;
        case Shape::plane: half = {size.x / 2.0, 0.0, size.z / 2.0}; break;
        case Shape::cylinder: half = {radius, height / 2.0, radius}; break;
        case Shape::mesh: return mesh ? mesh->bounds() : Aabb{};
    }
    return {-half, half};
}

Aabb SceneObject::world_bounds() const { return transformed(local_bounds(), model_matrix()); }

namespace {

// Does the ray from p along +x cross the triangle? (Möller and Trumbore, for the one fixed direction.)
bool crosses_along_x(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 direction{1.0, 0.0, 0.0}, ab = b - a, ac = c - a;
    const glm::dvec3 h = glm::cross(direction, ac);
    const double det = glm::dot(ab, h);
    if (det == 0.0) return false;  // the triangle is edge-on to the ray
    const glm::dvec3 s = p - a;
    const double u = glm::dot(s, h) / det;
    const glm::dvec3 q = glm::cross(s, ab);
    const double v = glm::dot(direction, q) / det;
    return u >= 0.0 && v >= 0.0 && u + v <= 1.0 && glm::dot(ac, q) / det > 0.0;
}

bool mesh_contains(const TriangleMesh& mesh, const glm::dvec3& local) {
    if (!mesh.bounds().contains(local)) return false;
    int crossings = 0;
    for (const std::array<int, 3>& t : mesh.triangles)
        crossings += crosses_along_x(local, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
    return crossings % 2 == 1;
}

}  // namespace

bool SceneObject::contains(const glm::dvec3& world) const {
    const glm::dvec3 local = glm::dvec3(glm::inverse(model_matrix()) * glm::dvec4(world, 1.0));
    switch (shape) {
        case Shape::box: return glm::all(glm::lessThanEqual(glm::abs(local), size / 2.0));
        case Shape::sphere: return glm::length(local) <= radius;
        case Shape::plane: return false;
        case Shape::cylinder: return std::hypot(local.x, local.z) <= radius && std::abs(local.y) <= height / 2.0;
        case Shape::mesh: return mesh && mesh_contains(*mesh, local);
    }
    return false;
}

}  // namespace shadowlab
