// glTF 2.0 scenes. The meshes come through Assimp (triangle_mesh: one object per node). The cameras,
// the KHR_lights_punctual lights and the nodes that place them are read here from the file's JSON,
// in double and with their JSON paths for messages: Assimp 5.2 gives a camera's horizontal field of
// view as yfov × aspect (not the angle), a missing zfar as 100 (not infinite), its node's translation
// twice (once as mPosition, once in the node's transform), and a light's range only as node metadata.
#include "scene/gltf_scene.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "io/value_text.hpp"
#include "limits.hpp"
#include "math/normalize.hpp"
#include "scene/file_bytes.hpp"
#include "scene/gltf_fields.hpp"
#include "scene/gltf_materials.hpp"
#include "scene/mesh_scene.hpp"
#include "scene/scene_error.hpp"
#include "scene/scene_validation.hpp"
#include "scene/triangle_mesh.hpp"

namespace shadowlab {
namespace {

using nlohmann::json;

// glTF gives a spot or point light's reach (`range`: where it fades to nothing) but no near plane;
// its maps start at this share of the reach.
constexpr double kRangeNearShare = 1e-3;
// A camera without `zfar` has its far plane at infinity; ShadowLab's camera needs a finite one, this
// many times the distance from the eye to the meshes' farthest corner.
constexpr double kFarBeyondMeshes = 2.0;
constexpr double kOrthographicNearShare = 1e-6;  // an orthographic camera's znear 0, as a share of zfar
// A spot's default outer cone angle (KHR_lights_punctual), from its axis.
constexpr double kDefaultOuterConeAngle = std::numbers::pi / 4.0;

std::string lowercase_extension(const std::string& file) {
    std::string extension = std::filesystem::path(file).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    return extension;
}

// ---- the file's JSON -------------------------------------------------------------------------

// A .glb is a 12-byte header (magic "glTF", version 2, length), then chunks of (length, type, data);
// the first chunk holds the JSON (glTF 2.0, "Binary glTF Layout"). Words are little-endian.
std::string glb_json(const std::string& bytes, const std::string& file) {
    const auto word = [&](std::size_t at) {
        std::uint32_t value = 0;
        for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(bytes[at + i]);
        return value;
    };
    constexpr std::uint32_t kMagic = 0x46546C67, kVersion = 2, kJsonChunk = 0x4E4F534A;  // "glTF", "JSON"
    constexpr std::size_t kJsonStart = 20;                                               // header and chunk head
    if (bytes.size() < kJsonStart || word(0) != kMagic)
        throw SceneError(file, "", "not a binary glTF: no \"glTF\" header");
    if (word(4) != kVersion)
        throw SceneError(file, "", "binary glTF version " + std::to_string(word(4)) + "; ShadowLab reads version 2");
    const std::uint32_t length = word(12);
    if (word(16) != kJsonChunk || length > bytes.size() - kJsonStart)
        throw SceneError(file, "", "binary glTF: its first chunk is not a whole JSON chunk");
    return bytes.substr(kJsonStart, length);
}

// glTF 1.0 (2015) keys its scenes, nodes and meshes by name in objects where 2.0 lists them in
// arrays: read as 2.0 it fails on its first object ("scenes: expected an array"), so it is named.
void refuse_gltf_1(const json& root, const std::string& file) {
    const auto asset = root.find("asset");
    const bool has_asset = asset != root.end() && asset->is_object();
    const auto version = has_asset ? asset->find("version") : root.end();
    const bool says_1 =
        has_asset && version != asset->end() && version->is_string() && version->get<std::string>().starts_with("1.");
    const auto scenes = root.find("scenes");
    const bool keyed_scenes = scenes != root.end() && scenes->is_object();
    if (says_1 || (keyed_scenes && !has_asset))
        throw SceneError(file, has_asset ? "asset.version" : "scenes", "a glTF 1.0 file; ShadowLab reads glTF 2.0");
}

json gltf_json(const std::string& file) {
    const std::string bytes = file_bytes(file);
    try {
        json root = json::parse(lowercase_extension(file) == ".glb" ? glb_json(bytes, file) : bytes);
        if (!root.is_object())
            throw SceneError(file, "", "expected a glTF JSON object, got " + std::string(root.type_name()));
        refuse_gltf_1(root, file);
        return root;
    } catch (const json::exception& error) {       // a syntax error, or a number beyond double's range
        const std::string message = error.what();  // "[json.exception.parse_error.101] parse error at line 3, ..."
        throw SceneError(file, "", "malformed JSON: " + message.substr(message.find(']') + 2));
    }
}

constexpr const char* kLightsPath = "extensions.KHR_lights_punctual.lights";

const json& cameras_of(const GltfFields& fields, const json& root) { return fields.array(root, "", "cameras"); }

const json& lights_of(const GltfFields& fields, const json& root) {
    const json* punctual = fields.nested(root, "", {"extensions", "KHR_lights_punctual"});
    return punctual ? fields.array(*punctual, "extensions.KHR_lights_punctual", "lights") : GltfFields::no_items();
}

const json& nodes_of(const GltfFields& fields, const json& root) { return fields.array(root, "", "nodes"); }

std::optional<std::size_t> camera_held(const GltfFields& fields, const json& root, const json& node,
                                       const std::string& path) {
    return fields.index(node, path, "camera", cameras_of(fields, root).size());
}

std::optional<std::size_t> light_held(const GltfFields& fields, const json& root, const json& node,
                                      const std::string& path) {
    const json* punctual = fields.nested(node, path, {"extensions", "KHR_lights_punctual"});
    return punctual ? fields.index(*punctual, path + ".extensions.KHR_lights_punctual", "light",
                                   lights_of(fields, root).size())
                    : std::nullopt;
}

// ---- what the file offers ----------------------------------------------------------------------

std::string optional_text(const GltfFields& fields, const json& object, const std::string& path, const char* key) {
    return fields.member(object, path, key) ? fields.text(object, path, key) : std::string();
}

// Each camera or light of `items` (at `items_path`; `held` gives the one a node holds) by its type and
// its own name, else that of the first node in the file's order holding it.
template <class Held>
std::vector<GltfItem> offered(const GltfFields& fields, const json& root, const json& items,
                              const std::string& items_path, Held held) {
    std::vector<GltfItem> out;
    for (std::size_t i = 0; i < items.size(); ++i) {
        const std::string path = indexed(items_path, i);
        GltfItem item{.name = optional_text(fields, items[i], path, "name"),
                      .type = fields.text(items[i], path, "type")};
        const json& nodes = nodes_of(fields, root);
        for (std::size_t node = 0; node < nodes.size() && item.name.empty(); ++node)
            if (held(fields, root, nodes[node], indexed("nodes", node)) == i)
                item.name = optional_text(fields, nodes[node], indexed("nodes", node), "name");
        out.push_back(std::move(item));
    }
    return out;
}

GltfContents contents_of(const GltfFields& fields, const json& root) {
    return {.cameras = offered(fields, root, cameras_of(fields, root), "cameras", camera_held),
            .lights = offered(fields, root, lights_of(fields, root), kLightsPath, light_held)};
}

// ---- nodes: where the cameras and lights stand ----------------------------------------------

// For each camera and light, the world transform of the first node holding it, depth first from the
// default scene's roots (as triangle_mesh orders the objects). A camera or light no node holds is
// nowhere.
struct Placements {
    std::map<std::size_t, glm::dmat4> world_from_camera, world_from_light;
};

class NodeWalk {
public:
    NodeWalk(const GltfFields& fields, const json& root) : fields_(fields), root_(root) {}

    Placements place() const {
        Placements placements;
        const json& scenes = fields_.array(root_, "", "scenes");
        if (scenes.empty()) return placements;
        const std::size_t scene = fields_.index(root_, "", "scene", scenes.size()).value_or(0);
        const std::string scene_path = indexed("scenes", scene);
        const json& roots = fields_.array(scenes[scene], scene_path, "nodes");
        std::vector<bool> reached(nodes().size(), false);
        // Depth first without recursion, so that a long chain of nodes cannot exhaust the stack.
        std::vector<std::pair<std::size_t, glm::dmat4>> pending;
        for (std::size_t i = roots.size(); i-- > 0;)
            pending.emplace_back(fields_.index(roots[i], indexed(scene_path + ".nodes", i), nodes().size()),
                                 glm::dmat4(1.0));
        while (!pending.empty()) {
            const auto [node, world_from_parent] = pending.back();
            pending.pop_back();
            const std::string path = indexed("nodes", node);
            if (reached[node])
                fields_.fail(path, "reached twice: a glTF node has one parent and is not its own ancestor");
            reached[node] = true;
            const glm::dmat4 world_from_node = world_from_parent * parent_from_node(nodes()[node], path);
            if (const auto camera = camera_held(fields_, root_, nodes()[node], path))
                placements.world_from_camera.try_emplace(*camera, world_from_node);
            if (const auto light = light_held(fields_, root_, nodes()[node], path))
                placements.world_from_light.try_emplace(*light, world_from_node);
            const json& children = fields_.array(nodes()[node], path, "children");
            for (std::size_t i = children.size(); i-- > 0;)
                pending.emplace_back(fields_.index(children[i], indexed(path + ".children", i), nodes().size()),
                                     world_from_node);
        }
        return placements;
    }

private:
    const json& nodes() const { return nodes_of(fields_, root_); }

    // glTF 2.0, "Transformations": a column-major `matrix`, or T * R * S from `translation`,
    // `rotation` (a unit quaternion, x, y, z, w) and `scale`.
    glm::dmat4 parent_from_node(const json& node, const std::string& path) const {
        if (const std::vector<double> m = fields_.numbers(node, path, "matrix", 16); !m.empty())
            return glm::make_mat4(m.data());
        glm::dmat4 transform(1.0);
        if (const std::vector<double> t = fields_.numbers(node, path, "translation", 3); !t.empty())
            transform = glm::translate(transform, glm::dvec3(t[0], t[1], t[2]));
        if (const std::vector<double> r = fields_.numbers(node, path, "rotation", 4); !r.empty()) {
            const glm::dquat rotation(r[3], r[0], r[1], r[2]);
            if (!(glm::length(rotation) > 0.0)) fields_.fail(path + ".rotation", "expected a unit quaternion, got 0");
            transform *= glm::mat4_cast(glm::normalize(rotation));
        }
        if (const std::vector<double> s = fields_.numbers(node, path, "scale", 3); !s.empty())
            transform = glm::scale(transform, glm::dvec3(s[0], s[1], s[2]));
        return transform;
    }

    const GltfFields& fields_;
    const json& root_;
};

// ---- cameras and lights ----------------------------------------------------------------------

glm::dvec3 world_point(const glm::dmat4& world_from_node, const glm::dvec3& p) {
    return glm::dvec3(world_from_node * glm::dvec4(p, 1.0));
}
glm::dvec3 world_direction(const glm::dmat4& world_from_node, const glm::dvec3& d) {
    return glm::dvec3(world_from_node * glm::dvec4(d, 0.0));
}

double farthest_corner_distance(const Aabb& box, const glm::dvec3& from) {
    double farthest = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p{corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                           corner & 4 ? box.max.z : box.min.z};
        farthest = std::max(farthest, glm::length(p - from));
    }
    return farthest;
}

glm::dvec3 normalize_or_zero(const glm::dvec3& v) {
    return v == glm::dvec3(0.0) ? v : normalize_safely(v);  // zero: a scale of 0, which validate_scene names
}

// A light shines down its node's −z from the node's origin (KHR_lights_punctual).
Light placed_light(Light light, const glm::dmat4& world_from_node) {
    light.position = world_point(world_from_node, glm::dvec3(0.0));
    light.direction = normalize_or_zero(world_direction(world_from_node, {0.0, 0.0, -1.0}));
    return light;
}

// A camera as the file gives it, and the node that places it.
struct PlacedLens {
    std::string path;  // cameras[i].perspective or cameras[i].orthographic
    CameraProjection projection = CameraProjection::perspective;
    double yfov = 0.0;  // perspective
    double ymag = 0.0;  // orthographic: half the view's height
    double znear = 0.0;
    std::optional<double> aspect, zfar;
    glm::dmat4 world_from_camera;
};

// The chosen camera and light, read and checked before the meshes are: a bad camera or light is named
// by its JSON path rather than by whatever Assimp makes of it.
class ChosenParts {
public:
    ChosenParts(const GltfFields& fields, const json& root, const Placements& placements,
                std::vector<std::string>& defaulted)
        : fields_(fields), root_(root), placements_(placements), defaulted_(defaulted) {}

    // The chosen camera's lens and node, or nullopt (said in `defaulted`) when the file has no camera
    // or no node holds the chosen one.
    std::optional<PlacedLens> lens(std::size_t chosen) const {
        const json& cameras = cameras_of(fields_, root_);
        if (cameras.empty()) {
            defaulted_.push_back(
                "no camera: the default one, looking at the meshes from the front and above, and a "
                "ground plane under them (a file without a camera is a model, not a scene)");
            return std::nullopt;
        }
        const std::string path = indexed("cameras", chosen);
        const std::string type = fields_.text(cameras[chosen], path, "type");
        if (type != "perspective" && type != "orthographic")
            fields_.fail(path + ".type", "expected \"perspective\" or \"orthographic\", got \"" + type + "\"");
        PlacedLens lens =
            type == "perspective" ? perspective(cameras[chosen], path) : orthographic(cameras[chosen], path);
        const auto placed = placements_.world_from_camera.find(chosen);
        if (placed == placements_.world_from_camera.end()) {
            defaulted_.push_back(path + " is held by no node of the scene: the default camera instead");
            return std::nullopt;
        }
        lens.world_from_camera = placed->second;
        return lens;
    }

    // The chosen light, or nullopt (said in `defaulted`) when the file has none or no node holds it.
    std::optional<Light> light(std::size_t chosen) const {
        const json& lights = lights_of(fields_, root_);
        if (lights.empty()) {
            defaulted_.push_back("no KHR_lights_punctual light: the default sun, high behind the camera");
            return std::nullopt;
        }
        const std::string path = indexed(kLightsPath, chosen);
        const Light light = punctual_light(lights[chosen], path);
        const auto placed = placements_.world_from_light.find(chosen);
        if (placed == placements_.world_from_light.end()) {
            defaulted_.push_back(path + " is held by no node of the scene: the default sun instead");
            return std::nullopt;
        }
        return placed_light(light, placed->second);
    }

private:
    PlacedLens perspective(const json& camera, const std::string& camera_path) const {
        const std::string path = camera_path + ".perspective";
        const json* lens = fields_.member(camera, camera_path, "perspective");
        if (!lens) fields_.fail(path, "required for a perspective camera, but missing");
        PlacedLens out{.path = path,
                       .yfov = fields_.required_number(*lens, path, "yfov"),
                       .znear = fields_.required_number(*lens, path, "znear"),
                       .aspect = fields_.number(*lens, path, "aspectRatio"),
                       .zfar = fields_.number(*lens, path, "zfar"),
                       .world_from_camera = glm::dmat4(1.0)};
        fields_.expect(out.yfov > 0.0 && out.yfov < std::numbers::pi, path + ".yfov", "an angle in (0, π) radians",
                       out.yfov);
        fields_.expect(out.znear > 0.0, path + ".znear", "a positive distance", out.znear);
        if (out.aspect) fields_.expect(*out.aspect > 0.0, path + ".aspectRatio", "a positive ratio", *out.aspect);
        if (out.zfar)
            fields_.expect(*out.zfar > out.znear, path + ".zfar", "a distance beyond znear (" + shown(out.znear) + ")",
                           *out.zfar);
        return out;
    }

    // glTF 2.0, "Orthographic projection": xmag and ymag the view's half width and height, zfar
    // required, znear >= 0 (0 is read as zfar / 1e6: ShadowLab's near plane is in front of the eye).
    PlacedLens orthographic(const json& camera, const std::string& camera_path) const {
        const std::string path = camera_path + ".orthographic";
        const json* lens = fields_.member(camera, camera_path, "orthographic");
        if (!lens) fields_.fail(path, "required for an orthographic camera, but missing");
        const double xmag = fields_.required_number(*lens, path, "xmag");
        PlacedLens out{.path = path,
                       .projection = CameraProjection::orthographic,
                       .ymag = fields_.required_number(*lens, path, "ymag"),
                       .znear = fields_.required_number(*lens, path, "znear"),
                       .zfar = fields_.required_number(*lens, path, "zfar"),
                       .world_from_camera = glm::dmat4(1.0)};
        fields_.expect(xmag > 0.0, path + ".xmag", "a positive half width", xmag);
        fields_.expect(out.ymag > 0.0, path + ".ymag", "a positive half height", out.ymag);
        fields_.expect(out.znear >= 0.0, path + ".znear", "a distance of 0 or more", out.znear);
        fields_.expect(*out.zfar > out.znear, path + ".zfar", "a distance beyond znear (" + shown(out.znear) + ")",
                       *out.zfar);
        out.aspect = xmag / out.ymag;
        if (out.znear == 0.0) {
            out.znear = *out.zfar * kOrthographicNearShare;
            defaulted_.push_back(path + " has znear 0: near = " + shown(out.znear) + ", zfar / 1e6");
        }
        return out;
    }

    // KHR_lights_punctual: a light's type, its spot cone and its range, before a node places it.
    Light punctual_light(const json& light, const std::string& path) const {
        const std::string type = fields_.text(light, path, "type");
        Light out;
        if (type == "directional") return out;  // `range` is for spot and point lights only
        if (type == "point")
            out.type = LightType::point;
        else if (type == "spot")
            out.type = LightType::spot;
        else
            fields_.fail(path + ".type", "expected \"directional\", \"point\" or \"spot\", got \"" + type + "\"");
        if (out.type == LightType::spot) {
            const json* spot = fields_.member(light, path, "spot");
            const double outer =
                spot ? fields_.number(*spot, path + ".spot", "outerConeAngle").value_or(kDefaultOuterConeAngle)
                     : kDefaultOuterConeAngle;
            // ShadowLab's cone is its full apex angle, below 180° (a map cannot hold a half-space).
            fields_.expect(outer > 0.0 && outer < std::numbers::pi / 2.0, path + ".spot.outerConeAngle",
                           "an angle in (0, π/2) radians", outer);
            out.cone_deg = glm::degrees(2.0 * outer);
        }
        if (const std::optional<double> range = fields_.number(light, path, "range")) {
            fields_.expect(*range > 0.0, path + ".range", "a positive distance", *range);
            out.range = LightRange{.near = kRangeNearShare * *range, .far = *range};
        }
        return out;
    }

    const GltfFields& fields_;
    const json& root_;
    const Placements& placements_;
    std::vector<std::string>& defaulted_;
};

// glTF 2.0, "Cameras": a camera looks down its node's −z, +y up. The target, which the window orbits
// about, lies ahead at the distance of the meshes' centre.
Camera placed_camera(const PlacedLens& lens, const Aabb& meshes, std::vector<std::string>& defaulted) {
    Camera camera;
    camera.projection = lens.projection;
    if (camera.is_orthographic())
        camera.half_height = lens.ymag;
    else
        camera.fov_y_deg = glm::degrees(lens.yfov);
    camera.near = lens.znear;
    camera.position = world_point(lens.world_from_camera, glm::dvec3(0.0));
    camera.up = world_direction(lens.world_from_camera, {0.0, 1.0, 0.0});
    const glm::dvec3 ahead = normalize_or_zero(world_direction(lens.world_from_camera, {0.0, 0.0, -1.0}));
    const double to_centre = glm::length(0.5 * (meshes.min + meshes.max) - camera.position);
    camera.target = camera.position + std::max(to_centre, lens.znear) * ahead;
    if (lens.aspect)
        camera.aspect = *lens.aspect;
    else
        defaulted.push_back(lens.path + " has no aspectRatio: " + shown(camera.aspect) + " (16:9)");
    if (lens.zfar) {
        camera.far = *lens.zfar;
    } else {
        camera.far = std::clamp(kFarBeyondMeshes * farthest_corner_distance(meshes, camera.position), 2.0 * lens.znear,
                                limits::far_over_near_max * lens.znear);
        defaulted.push_back(lens.path + " has no zfar (infinite): far = " + shown(camera.far) +
                            ", twice the distance to the meshes' farthest corner");
    }
    return camera;
}

// Each node holding meshes, as one object that casts and receives; its vertices already in the world,
// its materials' alpha tests and base colours beside it.
std::vector<SceneObject> node_objects(const std::string& file, const GltfMaterials& materials) {
    std::vector<SceneObject> objects;
    // Absolute: load_node_meshes reads a relative path as relative to the scene file's directory.
    for (NodeMesh& node : load_node_meshes(std::filesystem::absolute(file).string(), file, "meshes")) {
        SceneObject object;
        object.name = node.node_name.empty() ? "node_" + std::to_string(objects.size()) : node.node_name;
        object.shape = Shape::mesh;
        object.mesh_file = file;
        object.mesh = std::make_shared<const TriangleMesh>(std::move(node.mesh));
        if (std::any_of(materials.tests.begin(), materials.tests.end(),
                        [](const auto& test) { return test != nullptr; }))
            object.material_alpha = materials.tests;
        object.material_colour = materials.colours;
        objects.push_back(std::move(object));
    }
    return objects;
}

}  // namespace

bool is_gltf_file(const std::string& file) {
    const std::string extension = lowercase_extension(file);
    return extension == ".gltf" || extension == ".glb";
}

void check_choice(const std::string& file, const std::string& json_path, const std::string& what, std::size_t index,
                  std::size_t count, const std::string& holder) {
    if (index < count) return;
    const std::string held = count == 1
                                 ? "one " + what + " (0)"
                                 : std::to_string(count) + " " + what + "s (0 … " + std::to_string(count - 1) + ")";
    throw SceneError(file, json_path,
                     what + " " + std::to_string(index) + " asked for, but " + holder + " holds " + held);
}

GltfContents gltf_contents(const std::string& file) { return contents_of(GltfFields(file), gltf_json(file)); }

GltfScene read_gltf_scene(const std::string& file, const SceneChoice& choice) {
    GltfScene out = read_gltf_scene_unvalidated(file, choice);
    validate_scene(out.scene);
    return out;
}

GltfScene read_gltf_scene_unvalidated(const std::string& file, const SceneChoice& choice) {
    const json root = gltf_json(file);
    const GltfFields fields(file);
    const GltfContents contents = contents_of(fields, root);
    check_choice(file, "", "camera", choice.camera, contents.camera_choices(), "the file");
    check_choice(file, "", "light", choice.light, contents.light_choices(), "the file");
    const Placements placements = NodeWalk(fields, root).place();
    GltfScene out;
    const ChosenParts chosen(fields, root, placements, out.defaulted);
    const std::optional<PlacedLens> lens = chosen.lens(choice.camera);
    const std::optional<Light> light = chosen.light(choice.light);

    Scene& scene = out.scene;
    scene.name = std::filesystem::path(file).stem().string();
    scene.source_file = file;
    const GltfMaterials materials = read_gltf_materials(fields, root, file);
    scene.objects = node_objects(file, materials);
    scene.notes = materials.notes;
    const Aabb meshes = scene.bounds();
    scene.camera = lens ? placed_camera(*lens, meshes, out.defaulted) : camera_framing(meshes);
    scene.light = light.value_or(sun_beside(scene.camera));
    if (cameras_of(fields, root).empty())
        scene.objects.insert(scene.objects.begin(), ground_under(meshes, scene.light));
    return out;
}

}  // namespace shadowlab
