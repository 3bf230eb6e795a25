#pragma once
// What the window has open, in plain C++ (no Qt): the scene as it stands, the glTF file it came
// from, the camera before "Camera in shadow" moved it, and the inspection the views show. Each
// edit changes the scene at once; the window then computes its inspection off the GUI thread. A
// scene put in place (a file opened, another glTF camera or light) is on trial until its
// inspection lands: if it cannot be inspected, the scene before it comes back.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/inspection.hpp"
#include "scene/gltf_reference.hpp"
#include "scene/gltf_scene.hpp"

namespace shadowlab {

// The glTF file a scene comes from, which of its cameras and lights it took, and all it holds.
struct GltfSource {
    GltfReference reference;
    GltfContents contents;
};

class Session {
public:
    const Scene& scene() const { return scene_; }
    const std::optional<GltfSource>& gltf() const { return gltf_; }
    const Inspection* inspection() const { return inspection_.get(); }       // the one the views show
    std::shared_ptr<const Inspection> shown() const { return inspection_; }  // the same, shared

    // A scene JSON, a glTF scene or a mesh file, on trial; throws (naming the file and the field)
    // when it cannot be read, and the scene stays. Returns what loading assumed (loading_notes).
    std::vector<std::string> open_file(const std::string& path);
    // `scene` (read from `path`; empty: the same file read again) on trial in place of the one shown.
    void open(Scene scene, std::optional<GltfSource> gltf, const std::string& path);
    // The glTF file read again with another of its cameras or lights, the roles kept, on trial;
    // returns what was defaulted. Throws when it cannot be read, and the scene stays.
    std::vector<std::string> choose_from_gltf(const SceneChoice& choice);

    // The newest change's inspection, which the views now show. Returns the path of the file whose
    // opening it completes, if it does.
    std::optional<std::string> land(std::shared_ptr<const Inspection> inspection);
    // The newest change cannot be inspected: the views keep the inspection they show, and a scene on
    // trial gives way to the one before it. Returns whether one did.
    bool fail();

    // The camera orbited (in the Camera view): its new position, target and up.
    void orbit_camera(const glm::dvec3& position, const glm::dvec3& target, const glm::dvec3& up);
    // Another camera (an engine's, imported): "Camera in shadow" forgets where the camera was.
    void replace_camera(const Camera& camera);
    // The camera's position alone (its handle in the World view); its target stays. Refused (false)
    // on the target itself.
    bool move_camera_to(const glm::dvec3& position);
    void turn_light(const glm::dvec3& direction);
    // A directional light now shines from `point` toward the scene's centre; others move there.
    void move_light_to(const glm::dvec3& point);
    // Into a caster's shadow volume, or back where the camera was; false when no caster's shadow
    // has room for the camera above the ground.
    bool put_camera_in_shadow(bool inside);
    // An object's roles; throws, the roles unchanged, when the scene would break a rule (a light
    // inside a mesh that casts).
    void set_roles(size_t object, bool casts, bool receives);
    // The scene as a JSON referencing its glTF file, with the camera, light and roles chosen;
    // throws for a scene not from a glTF file.
    void save_scene(const std::string& json_file) const;

private:
    // A scene on trial, and what it replaced.
    struct Opening {
        std::string path;
        Scene previous;
        std::optional<GltfSource> previous_gltf;
        std::optional<Camera> previous_camera_outside;
    };

    Scene scene_;
    std::optional<GltfSource> gltf_;
    std::optional<Camera> camera_outside_;  // the camera before "Camera in shadow" moved it
    std::optional<Opening> opening_;
    std::shared_ptr<const Inspection> inspection_;
};

}  // namespace shadowlab
