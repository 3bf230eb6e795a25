#pragma once
// A scene: one camera, one light, objects.
#include <string>
#include <vector>

#include "geometry/aabb.hpp"
#include "notes/note.hpp"
#include "scene/camera.hpp"
#include "scene/light.hpp"
#include "scene/scene_object.hpp"

namespace shadowlab {

struct Scene {
    std::string name;
    std::string source_file;  // where it was loaded from (empty when built in code)
    Camera camera;
    Light light;
    std::vector<SceneObject> objects;
    std::vector<Note> notes;  // what loading degraded (a BLEND caster read as MASK)

    Aabb bounds() const;  // union of the objects' world bounds
};

// What loading left out of the scene's mesh files, one line per file (broken_faces_note), in the
// order the objects name them, then its notes (describe): for the window's messages.
std::vector<std::string> loading_notes(const Scene& scene);

}  // namespace shadowlab
