#include "scene/scene.hpp"

namespace shadowlab {

Aabb Scene::bounds() const {
    Aabb box;
    for (const SceneObject& object : objects) box.extend(object.world_bounds());
    return box;
}

}  // namespace shadowlab
