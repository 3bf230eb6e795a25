#include "scene_source.hpp"

#include "exchange/camera_import.hpp"

namespace shadowlab {

Scene load_scene_source(const std::string& file, const SceneSource& source) {
    Scene scene = load_scene(file, source.choice);
    if (!source.camera_matrices.empty())
        scene.camera =
            import_camera(source.camera_matrices, camera_conventions_from(source.camera_conventions), scene.bounds());
    return scene;
}

}  // namespace shadowlab
