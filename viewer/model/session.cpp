#include "model/session.hpp"

#include <filesystem>
#include <stdexcept>
#include <utility>

#include "model/camera_in_shadow.hpp"
#include "scene/scene_loader.hpp"

namespace shadowlab {

std::vector<std::string> Session::open_file(const std::string& path) {
    Scene loaded = load_scene(path);  // JSON, glTF (its own camera and light) or a lone mesh
    std::vector<std::string> notes = loading_notes(loaded);
    std::optional<GltfSource> gltf;
    if (std::optional<GltfReference> reference =
            gltf_reference_of(std::filesystem::absolute(path).lexically_normal().string()))
        gltf = GltfSource{.reference = *reference, .contents = gltf_contents(reference->gltf_file)};
    open(std::move(loaded), std::move(gltf), path);
    return notes;
}

void Session::open(Scene scene, std::optional<GltfSource> gltf, const std::string& path) {
    opening_ = Opening{.path = path,
                       .previous = std::exchange(scene_, std::move(scene)),
                       .previous_gltf = std::exchange(gltf_, std::move(gltf)),
                       .previous_camera_outside = std::exchange(camera_outside_, std::nullopt)};
}

std::vector<std::string> Session::choose_from_gltf(const SceneChoice& choice) {
    if (!gltf_) throw std::logic_error("the scene is not from a glTF file: it has no cameras or lights to choose");
    GltfReference reference = gltf_->reference;
    reference.choice = choice;
    reference.roles = roles_by_name(scene_, reference.gltf_file);
    reference.name = scene_.name;
    GltfScene chosen = referenced_scene(reference, scene_.source_file);
    GltfContents contents = gltf_->contents;
    open(std::move(chosen.scene), GltfSource{.reference = reference, .contents = std::move(contents)}, "");
    return chosen.defaulted;
}

std::optional<std::string> Session::land(std::shared_ptr<const Inspection> inspection) {
    inspection_ = std::move(inspection);
    std::optional<std::string> opened;
    if (opening_ && !opening_->path.empty()) opened = opening_->path;
    opening_.reset();
    return opened;
}

bool Session::fail() {
    if (!opening_) return false;
    Opening opened = *std::exchange(opening_, std::nullopt);
    scene_ = std::move(opened.previous);
    gltf_ = std::move(opened.previous_gltf);
    camera_outside_ = opened.previous_camera_outside;
    return true;
}

void Session::orbit_camera(const glm::dvec3& position, const glm::dvec3& target, const glm::dvec3& up) {
    scene_.camera.position = position, scene_.camera.target = target, scene_.camera.up = up;
}

void Session::replace_camera(const Camera& camera) {
    scene_.camera = camera;
    camera_outside_.reset();
}

bool Session::move_camera_to(const glm::dvec3& position) {
    if (!(glm::length(scene_.camera.target - position) > 0.0)) return false;
    scene_.camera.position = position;
    return true;
}

void Session::turn_light(const glm::dvec3& direction) { scene_.light.direction = direction; }

void Session::move_light_to(const glm::dvec3& point) {
    const Aabb bounds = scene_.bounds();
    const glm::dvec3 towards = 0.5 * (bounds.min + bounds.max) - point;
    if (!scene_.light.is_directional())
        scene_.light.position = point;
    else if (glm::length(towards) > 0.0)
        scene_.light.direction = glm::normalize(towards);
}

// Into a caster's shadow volume (z-pass fails there, z-fail holds), or back where the camera was.
bool Session::put_camera_in_shadow(bool inside) {
    if (inside && !camera_outside_) {
        const std::optional<Camera> moved = camera_in_shadow(scene_);
        if (!moved) return false;
        camera_outside_ = std::exchange(scene_.camera, *moved);
    } else if (!inside && camera_outside_) {
        scene_.camera = *std::exchange(camera_outside_, std::nullopt);
    }
    return true;
}

void Session::set_roles(size_t object, bool casts, bool receives) {
    SceneObject& changed = scene_.objects.at(object);
    const SceneObject before = changed;
    changed.casts = casts, changed.receives = receives;
    try {
        validate_scene(scene_);
    } catch (...) {
        changed = before;
        throw;
    }
}

void Session::save_scene(const std::string& json_file) const {
    if (!gltf_) throw std::invalid_argument("only a glTF scene is saved (as a JSON referencing its file)");
    save_scene_referencing_gltf(json_file, gltf_->reference.gltf_file, gltf_->reference.choice, scene_);
}

}  // namespace shadowlab
