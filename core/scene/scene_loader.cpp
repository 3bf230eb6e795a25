// Scene files (JSON). Every key is optional unless marked required; defaults are those of the
// scene/*.hpp headers (the first type listed is the default). A key that the object, light or
// camera does not use is an error.
//
// { "name": "...", "description": "...",
//   "camera":  {"projection": "perspective" | "orthographic",
//               "position": [x,y,z], "target": [x,y,z], "up": [0,1,0],
//               "fov_y_deg": 60,                                 // perspective
//               "half_height": 1,                                // orthographic: half the view's height
//               "aspect": 1.7778, "near": 0.1, "far": 100},
//   "light":   {"type": "directional" | "spot" | "point",         // required object
//               "direction": [x,y,z],                            // directional, spot
//               "position": [x,y,z],                             // spot, point
//               "cone_deg": 60,                                  // spot: full apex angle
//               "range": [near, far],                            // spot, point: the distances lit
//               "radius": 0,                                     // spot, point: a sphere light (soft)
//               "angular_radius_deg": 0},                        // directional: the sun's disc (soft)
//   "objects": [                                                 // required, non-empty
//     {"type": "box" | "sphere" | "plane" | "cylinder" | "mesh", "name": "<type>_<index>",
//      "position": [x,y,z], "rotation": [degrees about x, y, z], "scale": [x,y,z] or s,
//      "casts": true, "receives": true,
//      "size": [x,y,z] (box) or [x,z] (plane), "radius": r (sphere, cylinder),
//      "height": h (cylinder), "file": "path relative to the scene file" (mesh, required)}]}
//
// Or a glTF scene referenced (gltf_reference), told apart by its "gltf" key:
//
// { "name": "<the glTF file's stem>", "description": "...",
//   "gltf": "path relative to the scene file",                   // required
//   "camera": 0, "light": 0,                                     // which of the file's, 0-based
//   "objects": {"<object name>": {"casts": true, "receives": true}}}
//
// The numeric rules are validate_scene's (scene_validation.hpp); a syntax error is placed by its line
// and column (json_position.hpp).
#include "scene/scene_loader.hpp"

#include <algorithm>
#include <cctype>
#include <array>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>

#include "math/normalize.hpp"
#include "scene/file_bytes.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/json_position.hpp"
#include "scene/mesh_scene.hpp"
#include "scene/scene_error.hpp"

namespace shadowlab {
namespace {

using nlohmann::json;

constexpr std::size_t kMaxShownChars = 80;  // longer JSON values are shortened in messages

constexpr std::array kShapes{Shape::box, Shape::sphere, Shape::plane, Shape::cylinder, Shape::mesh};
constexpr std::array kLightTypes{LightType::directional, LightType::spot, LightType::point};
constexpr std::array kProjections{CameraProjection::perspective, CameraProjection::orthographic};

// A JSON value as shown in messages, shortened when long.
std::string show(const json& value) {
    const std::string text = value.dump();
    return text.size() <= kMaxShownChars ? text : text.substr(0, kMaxShownChars - 3) + "...";
}

// ---- JSON structure: keys and types --------------------------------------------------------

std::vector<std::string> camera_keys(CameraProjection projection) {
    const char* lens = projection == CameraProjection::orthographic ? "half_height" : "fov_y_deg";
    return {"projection", "position", "target", "up", lens, "aspect", "near", "far"};
}

std::vector<std::string> light_keys(LightType type) {
    switch (type) {
        case LightType::directional: return {"type", "direction", "angular_radius_deg"};
        case LightType::spot: return {"type", "direction", "position", "cone_deg", "range", "radius"};
        case LightType::point: return {"type", "position", "range", "radius"};
    }
    return {};
}

std::vector<std::string> object_keys(Shape shape) {
    std::vector<std::string> keys{"type", "name", "position", "rotation", "scale", "casts", "receives"};
    switch (shape) {
        case Shape::box: keys.push_back("size"); break;
        case Shape::sphere: keys.push_back("radius"); break;
        case Shape::plane: keys.push_back("size"); break;
        case Shape::cylinder: keys.insert(keys.end(), {"radius", "height"}); break;
        case Shape::mesh: keys.push_back("file"); break;
    }
    return keys;
}

const json* find_field(const json& object, const char* key) {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

// Reads the document into a Scene, checking keys and types; the numeric rules are
// validate_scene's. Meshes are loaded here, each file once.
class SceneReader {
public:
    explicit SceneReader(const std::string& file) : file_(file) {}

    Scene read(const json& root) {
        expect_object(root, "");
        check_keys(root, "", {"name", "description", "camera", "light", "objects"}, "a scene");
        Scene scene;
        scene.source_file = file_;
        std::string description;  // documentation only
        read_field(root, "", "name", scene.name);
        read_field(root, "", "description", description);
        if (const json* camera = find_field(root, "camera")) scene.camera = read_camera(*camera);
        scene.light = read_light(required(root, "light"));
        scene.objects = read_objects(required(root, "objects"));
        scene.notes = notes_;
        return scene;
    }

    GltfReference read_reference(const json& root) const {
        check_keys(root, "", {"name", "description", "gltf", "camera", "light", "objects"},
                   "a scene referencing a glTF file");
        GltfReference reference;
        std::string description, gltf_file;  // description: documentation only
        read_field(root, "", "name", reference.name);
        read_field(root, "", "description", description);
        read_field(root, "", "gltf", gltf_file);
        reference.gltf_file = relative_to_scene(gltf_file);
        read_field(root, "", "camera", reference.choice.camera);
        read_field(root, "", "light", reference.choice.light);
        if (const json* objects = find_field(root, "objects")) reference.roles = read_roles(*objects);
        return reference;
    }

private:
    [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
        throw SceneError(file_, path, problem);
    }
    void expect(bool ok, const std::string& path, const std::string& expected, const json& got) const {
        if (!ok) fail(path, "expected " + expected + ", got " + show(got));
    }
    void expect_object(const json& value, const std::string& path) const {
        expect(value.is_object(), path, "an object", value);
    }
    const json& required(const json& object, const char* key) const {
        const json* value = find_field(object, key);
        if (!value) fail(key, "required, but missing");
        return *value;
    }
    void check_keys(const json& object, const std::string& path, const std::vector<std::string>& allowed,
                    const std::string& owner) const {
        for (const auto& [key, value] : object.items())
            if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
                fail(join_path(path, key), "unknown key; allowed for " + owner + ": " + join(allowed));
    }

    // One parse() per field type, so that read_field() serves them all.
    void parse(const json& value, const std::string& path, double& out) const {
        expect(value.is_number(), path, "a number", value);
        out = value.get<double>();
    }
    void parse(const json& value, const std::string& path, glm::dvec3& out) const {
        const std::vector<double> v = numbers(value, path, 3);
        out = {v[0], v[1], v[2]};
    }
    void parse(const json& value, const std::string& path, bool& out) const {
        expect(value.is_boolean(), path, "true or false", value);
        out = value.get<bool>();
    }
    void parse(const json& value, const std::string& path, std::size_t& out) const {
        expect(value.is_number_unsigned(), path, "an index: 0, 1, ...", value);
        out = value.get<std::size_t>();
    }
    void parse(const json& value, const std::string& path, std::string& out) const {
        expect(value.is_string(), path, "a string", value);
        out = value.get<std::string>();
    }
    void parse(const json& value, const std::string& path, Shape& out) const { out = parse_enum(value, path, kShapes); }
    void parse(const json& value, const std::string& path, LightType& out) const {
        out = parse_enum(value, path, kLightTypes);
    }
    void parse(const json& value, const std::string& path, CameraProjection& out) const {
        out = parse_enum(value, path, kProjections);
    }
    template <class T>
    void read_field(const json& object, const std::string& path, const char* key, T& out) const {
        if (const json* value = find_field(object, key)) parse(*value, join_path(path, key), out);
    }

    std::vector<double> numbers(const json& value, const std::string& path, std::size_t count) const {
        const bool ok = value.is_array() && value.size() == count &&
                        std::all_of(value.begin(), value.end(), [](const json& item) { return item.is_number(); });
        expect(ok, path, "an array of " + count_of(count), value);
        std::vector<double> out;
        for (const json& item : value) out.push_back(item.get<double>());
        return out;
    }
    template <class Enum, std::size_t N>
    Enum parse_enum(const json& value, const std::string& path, const std::array<Enum, N>& all) const {
        std::vector<std::string> names;
        for (Enum item : all) {
            if (value.is_string() && value.get<std::string>() == to_string(item)) return item;
            names.push_back('"' + std::string(to_string(item)) + '"');
        }
        fail(path, "expected one of " + join(names) + ", got " + show(value));
    }

    Camera read_camera(const json& value) const {
        const std::string path = "camera";
        expect_object(value, path);
        Camera camera;
        read_field(value, path, "projection", camera.projection);
        check_keys(value, path, camera_keys(camera.projection),
                   std::string(camera.is_orthographic() ? "an " : "a ") + to_string(camera.projection) + " camera");
        read_field(value, path, "position", camera.position);
        read_field(value, path, "target", camera.target);
        read_field(value, path, "up", camera.up);
        read_field(value, path, "fov_y_deg", camera.fov_y_deg);
        read_field(value, path, "half_height", camera.half_height);
        read_field(value, path, "aspect", camera.aspect);
        read_field(value, path, "near", camera.near);
        read_field(value, path, "far", camera.far);
        return camera;
    }

    Light read_light(const json& value) const {
        const std::string path = "light";
        expect_object(value, path);
        Light light;
        read_field(value, path, "type", light.type);
        check_keys(value, path, light_keys(light.type), std::string("a ") + to_string(light.type) + " light");
        read_field(value, path, "direction", light.direction);
        read_field(value, path, "position", light.position);
        read_field(value, path, "cone_deg", light.cone_deg);
        read_field(value, path, "radius", light.radius);
        read_field(value, path, "angular_radius_deg", light.angular_radius_deg);
        if (const json* range = find_field(value, "range")) {
            const std::vector<double> near_far = numbers(*range, path + ".range", 2);
            light.range = LightRange{.near = near_far[0], .far = near_far[1]};
        }
        return light;
    }

    std::string relative_to_scene(const std::string& file) const {
        const std::filesystem::path path(file);
        return path.is_absolute() ? file
                                  : (std::filesystem::path(file_).parent_path() / path).lexically_normal().string();
    }

    std::map<std::string, ObjectRoles> read_roles(const json& value) const {
        expect(value.is_object(), "objects", "an object of object names and their roles", value);
        std::map<std::string, ObjectRoles> roles;
        for (const auto& [name, named] : value.items()) {
            const std::string path = join_path("objects", name);
            expect_object(named, path);
            check_keys(named, path, {"casts", "receives"}, "an object's roles");
            read_field(named, path, "casts", roles[name].casts);
            read_field(named, path, "receives", roles[name].receives);
        }
        return roles;
    }

    std::vector<SceneObject> read_objects(const json& value) {
        expect(value.is_array(), "objects", "an array of objects", value);
        std::vector<SceneObject> objects;
        for (std::size_t i = 0; i < value.size(); ++i)
            objects.push_back(read_object(value[i], "objects[" + std::to_string(i) + "]", i));
        return objects;
    }

    SceneObject read_object(const json& value, const std::string& path, std::size_t index) {
        expect_object(value, path);
        SceneObject object;
        read_field(value, path, "type", object.shape);
        check_keys(value, path, object_keys(object.shape), std::string("a ") + to_string(object.shape));
        object.name = std::string(to_string(object.shape)) + "_" + std::to_string(index);
        read_field(value, path, "name", object.name);
        read_field(value, path, "position", object.position);
        read_field(value, path, "rotation", object.rotation_deg);
        read_field(value, path, "radius", object.radius);
        read_field(value, path, "height", object.height);
        read_field(value, path, "casts", object.casts);
        read_field(value, path, "receives", object.receives);
        if (const json* scale = find_field(value, "scale")) object.scale = read_scale(*scale, join_path(path, "scale"));
        if (const json* size = find_field(value, "size"))
            object.size = read_size(*size, join_path(path, "size"), object);
        if (object.shape == Shape::mesh) load_mesh(value, join_path(path, "file"), object);
        return object;
    }

    glm::dvec3 read_scale(const json& value, const std::string& path) const {
        if (value.is_number()) return glm::dvec3(value.get<double>());
        expect(value.is_array(), path, "a number or an array of three numbers", value);
        glm::dvec3 scale;
        parse(value, path, scale);
        return scale;
    }

    // A box has three extents, a plane two: [x, z].
    glm::dvec3 read_size(const json& value, const std::string& path, const SceneObject& object) const {
        if (object.shape == Shape::box) {
            glm::dvec3 size;
            parse(value, path, size);
            return size;
        }
        const std::vector<double> xz = numbers(value, path, 2);
        return {xz[0], object.size.y, xz[1]};
    }

    void load_mesh(const json& value, const std::string& path, SceneObject& object) {
        const json* file = find_field(value, "file");
        if (!file) fail(path, "required for a mesh, but missing");
        parse(*file, path, object.mesh_file);
        std::shared_ptr<const TriangleMesh>& mesh = meshes_[object.mesh_file];
        std::vector<std::shared_ptr<const BaseColour>>& colours = colours_[object.mesh_file];
        if (!mesh) {  // each file's notes once
            mesh = std::make_shared<const TriangleMesh>(load_triangle_mesh(object.mesh_file, file_, path));
            colours = material_colours(*mesh, object.mesh_file, file_, notes_);
        }
        object.mesh = mesh;
        object.material_alpha = opacity_alpha_tests(*mesh, object.mesh_file, file_, path);
        object.material_colour = colours;
    }

    const std::string& file_;
    std::map<std::string, std::shared_ptr<const TriangleMesh>> meshes_;
    std::map<std::string, std::vector<std::shared_ptr<const BaseColour>>> colours_;
    std::vector<Note> notes_;  // what loading the meshes degraded
};

// The scene, what loading it degraded said on stderr.
Scene told(Scene scene, const std::string& file) {
    for (const Note& note : scene.notes) std::clog << file << ": " << describe(note) << "\n";
    return scene;
}

// The scene, what the glTF file lacks and what loading it degraded said on stderr.
Scene told(GltfScene gltf, const std::string& gltf_file) {
    for (const std::string& assumed : gltf.defaulted) std::clog << gltf_file << ": " << assumed << "\n";
    return told(std::move(gltf.scene), gltf_file);
}

bool references_gltf(const json& root) { return root.is_object() && root.contains("gltf"); }

// What a file is: a glTF scene by its extension (.gltf, .glb), a scene JSON by its extension (.json)
// or by its first byte that is not blank being '{', a mesh by any other extension Assimp reads, and
// otherwise, whatever its name, by its content: a scene JSON when it begins as one, else a model
// for Assimp, which tells formats by their signatures (a 3DS file named without an extension).
enum class SceneFileKind { gltf, scene_json, mesh };

bool begins_as_json_object(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char c = 0;
    while (in.get(c))
        if (!std::isspace(static_cast<unsigned char>(c))) return c == '{';
    return false;
}

SceneFileKind scene_file_kind(const std::string& path) {
    if (is_gltf_file(path)) return SceneFileKind::gltf;
    if (std::filesystem::path(path).extension() == ".json") return SceneFileKind::scene_json;
    if (is_mesh_file(path)) return SceneFileKind::mesh;
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error) || begins_as_json_object(path)) return SceneFileKind::scene_json;
    return SceneFileKind::mesh;
}

}  // namespace

Scene load_scene(const std::string& path, const SceneChoice& choice) {
    const SceneFileKind kind = scene_file_kind(path);
    if (kind == SceneFileKind::gltf) return told(read_gltf_scene(path, choice), path);
    // A scene JSON or a lone mesh holds one of each; a JSON referencing a glTF scene has chosen.
    check_choice(path, "", "camera", choice.camera, 1, "the file");
    check_choice(path, "", "light", choice.light, 1, "the file");
    if (kind == SceneFileKind::mesh) return told(scene_around_mesh(path), path);
    return parse_scene(file_bytes(path), path);
}

Scene parse_scene(const std::string& json_text, const std::string& file) {
    const json root = parse_scene_json(json_text, file);
    if (references_gltf(root)) {
        const GltfReference reference = SceneReader(file).read_reference(root);
        return told(referenced_scene(reference, file), reference.gltf_file);
    }
    Scene scene = SceneReader(file).read(root);
    validate_scene(scene);
    scene.light.direction = normalize_safely(scene.light.direction);
    scene.camera.up = normalize_safely(scene.camera.up);
    return told(std::move(scene), file);
}

std::optional<GltfReference> gltf_reference_of(const std::string& path, const SceneChoice& choice) {
    const SceneFileKind kind = scene_file_kind(path);
    if (kind == SceneFileKind::gltf) return GltfReference{.gltf_file = path, .choice = choice, .roles = {}, .name = {}};
    if (kind == SceneFileKind::mesh) return std::nullopt;
    const json root = parse_scene_json(file_bytes(path), path);
    if (!references_gltf(root)) return std::nullopt;
    return SceneReader(path).read_reference(root);
}

}  // namespace shadowlab
