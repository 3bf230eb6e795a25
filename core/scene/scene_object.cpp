#include "scene/scene_object.hpp"

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

}  // namespace shadowlab
