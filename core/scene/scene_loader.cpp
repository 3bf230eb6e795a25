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
// Numeric rules (validate_scene; the ranges are limits.hpp's): all numbers finite; positions
// within ±1e12, and so every corner of a placed object; sizes, radius, height, near, far and
// half_height in [1e-6, 1e12]; scale in [1e-6, 1e6]; aspect in [1e-3, 1e3]; near < far <= 1e9 near;
// fov_y_deg and cone_deg in (0, 180); directions non-zero (normalised after loading); camera target
// != position and up not parallel to the view direction; a light range 0 < near < far within
// [1e-6, 1e12]; a spot or point light outside every caster (a map from inside a box sees only the box).
#include "scene/scene_loader.hpp"

#include <algorithm>
#include <cctype>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>

#include "limits.hpp"
#include "math/normalize.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/mesh_scene.hpp"
#include "scene/scene_error.hpp"

namespace shadowlab {
namespace {

using nlohmann::json;

constexpr double kMinLength = 1e-12;        // camera target closer to position counts as equal
constexpr double kMinSineToView = 1e-6;     // camera up closer to the view direction is parallel
constexpr std::size_t kMaxShownChars = 80;  // longer JSON values are shortened in messages

constexpr std::array kShapes{Shape::box, Shape::sphere, Shape::plane, Shape::cylinder, Shape::mesh};
constexpr std::array kLightTypes{LightType::directional, LightType::spot, LightType::point};
constexpr std::array kProjections{CameraProjection::perspective, CameraProjection::orthographic};

std::string join_path(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

std::string join(const std::vector<std::string>& items) {
    std::string out;
    for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
    return out;
}

std::string format_number(double value) {
    std::ostringstream out;
    out << std::setprecision(15) << value;
    return out.str();
}

std::vector<double> components(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

double largest_magnitude(const glm::dvec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

std::string format_numbers(const std::vector<double>& values) {
    if (values.size() == 1) return format_number(values[0]);
    std::vector<std::string> items;
    for (double value : values) items.push_back(format_number(value));
    std::string out = "[";  // not "[" + ...: GCC 12 warns falsely (-Wrestrict)
    out += join(items);
    return out += "]";
}

// A JSON value as shown in messages, shortened when long.
std::string show(const json& value) {
    const std::string text = value.dump();
    return text.size() <= kMaxShownChars ? text : text.substr(0, kMaxShownChars - 3) + "...";
}

// "three numbers", "a positive number", "two finite numbers".
std::string count_of(std::size_t count, const std::string& adjective = "") {
    static const char* const words[] = {"no", "a", "two", "three"};
    const std::string word = count < 4 ? words[count] : std::to_string(count);
    return word + (adjective.empty() ? "" : " " + adjective) + (count == 1 ? " number" : " numbers");
}

// ---- JSON syntax ---------------------------------------------------------------------------

// A SAX pass that only tracks where it is, so that a syntax error is reported with its line and
// column, and a number too large for a double (1e999; nlohmann refuses it) with its JSON path.
class JsonErrorLocator final : public nlohmann::json_sax<json> {
public:
    explicit JsonErrorLocator(const std::string& file) : file_(file) {}

    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override { return open(false); }
    bool key(string_t& key) override {
        levels_.back().key = key;
        return true;
    }
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(true); }
    bool end_array() override { return close(); }

    bool parse_error(std::size_t, const std::string& token, const json::exception& error) override {
        if (error.id == 406)  // "number overflow": the only error with a known JSON path
            throw SceneError(file_, path(), "expected a finite number, got " + token);
        const std::string message = error.what();
        const std::string marker = "parse error at ";  // followed by "line L, column C: ..."
        const std::size_t at = message.find(marker);
        if (at == std::string::npos) throw SceneError(file_, "", "malformed JSON: " + message);
        throw SceneError(file_, "", "malformed JSON at " + message.substr(at + marker.size()));
    }

private:
    struct Level {
        bool array;
        std::size_t index = 0;  // arrays: the element being read
        std::string key;        // objects: the member being read
    };

    bool open(bool array) {
        levels_.push_back({array, 0, {}});
        return true;
    }
    bool close() {
        levels_.pop_back();
        return value();
    }
    bool value() {
        if (!levels_.empty() && levels_.back().array) ++levels_.back().index;
        return true;
    }
    std::string path() const {
        std::string out;
        for (const Level& level : levels_)
            out = level.array ? out + "[" + std::to_string(level.index) + "]" : join_path(out, level.key);
        return out;
    }

    const std::string& file_;
    std::vector<Level> levels_;
};

json parse_json(const std::string& text, const std::string& file) {
    JsonErrorLocator locator(file);
    json::sax_parse(text, &locator);
    return json::parse(text);
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
        if (!mesh) mesh = std::make_shared<const TriangleMesh>(load_triangle_mesh(object.mesh_file, file_, path));
        object.mesh = mesh;
    }

    const std::string& file_;
    std::map<std::string, std::shared_ptr<const TriangleMesh>> meshes_;
};

// ---- Numeric rules -------------------------------------------------------------------------

class SceneValidator {
public:
    explicit SceneValidator(const std::string& file) : file_(file) {}

    void check(const Scene& scene) const {
        check_camera(scene.camera);
        check_light(scene.light);
        if (scene.objects.empty()) fail("objects", "expected at least one object, got none");
        if (!limits::within(limits::scene_objects, std::int64_t(scene.objects.size())))
            fail("objects", limits::outside(limits::scene_objects, "count", std::int64_t(scene.objects.size())));
        for (std::size_t i = 0; i < scene.objects.size(); ++i)
            check_object(scene.objects[i], "objects[" + std::to_string(i) + "]");
        check_mesh_triangles(scene);
        check_light_outside_casters(scene);
    }

private:
    [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
        throw SceneError(file_, path, problem);
    }
    void expect(bool ok, const std::string& path, const std::string& expected, const std::vector<double>& got) const {
        if (!ok) fail(path, "expected " + expected + ", got " + format_numbers(got));
    }

    void check_numbers(const std::vector<double>& values, const std::string& path, bool positive) const {
        const auto all = [&](auto predicate) { return std::all_of(values.begin(), values.end(), predicate); };
        expect(all([](double x) { return std::isfinite(x); }), path, count_of(values.size(), "finite"), values);
        if (positive) expect(all([](double x) { return x > 0.0; }), path, count_of(values.size(), "positive"), values);
    }
    // Each value within the range, named by its own path: camera.position[0].
    void check_range(const std::vector<double>& values, const std::string& path, const limits::RealRange& range) const {
        for (std::size_t i = 0; i < values.size(); ++i)
            expect(limits::within(range, values[i]), values.size() == 1 ? path : path + "[" + std::to_string(i) + "]",
                   "a number within " + limits::shown(range), {values[i]});
    }
    void finite(const std::vector<double>& values, const std::string& path) const {
        check_numbers(values, path, false);
    }
    // Finite, and within ±1e12.
    void coordinates(const glm::dvec3& v, const std::string& path) const {
        finite(components(v), path);
        check_range(components(v), path, limits::coordinate);
    }
    // Positive, and within the range (lengths, scales, the aspect).
    void positive(const std::vector<double>& values, const std::string& path, const limits::RealRange& range) const {
        check_numbers(values, path, true);
        check_range(values, path, range);
    }
    void direction(const glm::dvec3& v, const std::string& path) const {
        finite(components(v), path);
        expect(largest_magnitude(v) > 0.0, path, "a non-zero direction", components(v));
    }
    // Finite, 0 or more, below `max` (0 means off).
    void non_negative(double value, const std::string& path, double max) const {
        finite({value}, path);
        std::ostringstream bound;  // 45, 1e+12: short
        bound << max;
        expect(value >= 0.0 && value < max, path, "a number in [0, " + bound.str() + ")", {value});
    }
    void angle(double degrees, const std::string& path) const {
        finite({degrees}, path);
        expect(limits::within(limits::angle_deg, degrees), path,
               "an angle in " + limits::shown(limits::angle_deg) + " degrees", {degrees});
    }

    void check_camera(const Camera& camera) const {
        coordinates(camera.position, "camera.position");
        coordinates(camera.target, "camera.target");
        expect(glm::length(camera.target - camera.position) > kMinLength, "camera.target",
               "a point different from position", components(camera.target));
        direction(camera.up, "camera.up");
        const double sine = glm::length(glm::cross(normalize_safely(camera.up), camera.view_direction()));
        expect(sine > kMinSineToView, "camera.up", "a direction not parallel to the view direction",
               components(camera.up));
        if (camera.is_orthographic())
            positive({camera.half_height}, "camera.half_height", limits::length);
        else
            angle(camera.fov_y_deg, "camera.fov_y_deg");
        positive({camera.aspect}, "camera.aspect", limits::aspect);
        positive({camera.near}, "camera.near", limits::length);
        check_far(camera.near, camera.far);
    }

    void check_far(double near, double far) const {
        finite({far}, "camera.far");
        if (!(far > near))
            fail("camera.far", "must be greater than near (" + format_number(near) + "), got " + format_number(far));
        check_range({far}, "camera.far", limits::length);
        if (far > limits::far_over_near_max * near)
            fail("camera.far", "must be at most " + limits::shown(limits::far_over_near_max) + " times near (" +
                                   format_number(near) + "), got " + format_number(far));
    }

    // Only the fields the light's type uses.
    void check_light(const Light& light) const {
        if (light.type != LightType::point) direction(light.direction, "light.direction");
        if (light.type != LightType::directional) coordinates(light.position, "light.position");
        if (light.type == LightType::spot) angle(light.cone_deg, "light.cone_deg");
        // Area lights: 0 is a point (hard shadows); a sun wider than 45° is no longer a sun.
        non_negative(light.radius, "light.radius", limits::length.max);
        non_negative(light.angular_radius_deg, "light.angular_radius_deg", 45.0);
        if (light.range) {
            positive({light.range->near, light.range->far}, "light.range", limits::length);
            if (!(light.range->far > light.range->near))
                fail("light.range[1]", "must be greater than near (" + format_number(light.range->near) + "), got " +
                                           format_number(light.range->far));
        }
    }

    // A spot or point light inside a caster sees only that caster's inside: every map is black.
    void check_light_outside_casters(const Scene& scene) const {
        if (scene.light.is_directional()) return;
        for (std::size_t i = 0; i < scene.objects.size(); ++i) {
            const SceneObject& object = scene.objects[i];
            if (object.casts && object.contains(scene.light.position))
                fail("light.position", "inside the caster objects[" + std::to_string(i) + "] (" + object.name +
                                           "): its map would see nothing but that object");
        }
    }

    // Only the fields the object's shape uses.
    // Meshes' triangles, each object counted (a file used twice is drawn twice).
    void check_mesh_triangles(const Scene& scene) const {
        std::int64_t triangles = 0;
        for (std::size_t i = 0; i < scene.objects.size(); ++i) {
            if (!scene.objects[i].mesh) continue;
            triangles += std::int64_t(scene.objects[i].mesh->triangles.size());
            if (triangles > limits::scene_triangles.max)
                fail("objects[" + std::to_string(i) + "].file",
                     limits::outside(limits::scene_triangles, "mesh triangles up to this object", triangles));
        }
    }

    void check_object(const SceneObject& object, const std::string& path) const {
        coordinates(object.position, path + ".position");
        finite(components(object.rotation_deg), path + ".rotation");
        positive(components(object.scale), path + ".scale", limits::scale);
        switch (object.shape) {
            case Shape::box: positive(components(object.size), path + ".size", limits::length); break;
            case Shape::plane:  // [x, z]
                positive({object.size.x, object.size.z}, path + ".size", limits::length);
                break;
            case Shape::sphere: positive({object.radius}, path + ".radius", limits::length); break;
            case Shape::cylinder:
                positive({object.radius}, path + ".radius", limits::length);
                positive({object.height}, path + ".height", limits::length);
                break;
            case Shape::mesh:
                if (!object.mesh) fail(path + ".file", "mesh not loaded: " + object.mesh_file);
                break;
        }
        check_placed(object, path);
    }

    // Each field within its range can still place a corner beyond ±1e12: a large scale times a
    // large size, or a large mesh, far from the origin.
    void check_placed(const SceneObject& object, const std::string& path) const {
        const Aabb box = object.world_bounds();
        const double reach = std::max(largest_magnitude(box.min), largest_magnitude(box.max));
        if (!limits::within(limits::coordinate, reach))
            fail(path, "expected every corner within " + limits::shown(limits::coordinate) +
                           " once placed (position, scale and size together), got a corner at " + format_number(reach));
    }

    const std::string& file_;
};

// The scene, what the glTF file lacks said on stderr.
Scene told(GltfScene gltf, const std::string& gltf_file) {
    for (const std::string& assumed : gltf.defaulted) std::clog << gltf_file << ": " << assumed << "\n";
    return std::move(gltf.scene);
}

bool references_gltf(const json& root) { return root.is_object() && root.contains("gltf"); }

std::string file_text(const std::string& path) {
    std::error_code error;
    std::ifstream in(path, std::ios::binary);
    if (!std::filesystem::is_regular_file(path, error) || !in) throw SceneError(path, "", "cannot open file");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

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
    if (kind == SceneFileKind::mesh) return scene_around_mesh(path);
    return parse_scene(file_text(path), path);
}

Scene parse_scene(const std::string& json_text, const std::string& file) {
    const json root = parse_json(json_text, file);
    if (references_gltf(root)) {
        const GltfReference reference = SceneReader(file).read_reference(root);
        return told(referenced_scene(reference, file), reference.gltf_file);
    }
    Scene scene = SceneReader(file).read(root);
    validate_scene(scene);
    scene.light.direction = normalize_safely(scene.light.direction);
    scene.camera.up = normalize_safely(scene.camera.up);
    return scene;
}

std::optional<GltfReference> gltf_reference_of(const std::string& path, const SceneChoice& choice) {
    const SceneFileKind kind = scene_file_kind(path);
    if (kind == SceneFileKind::gltf) return GltfReference{.gltf_file = path, .choice = choice, .roles = {}, .name = {}};
    if (kind == SceneFileKind::mesh) return std::nullopt;
    const json root = parse_json(file_text(path), path);
    if (!references_gltf(root)) return std::nullopt;
    return SceneReader(path).read_reference(root);
}

void validate_scene(const Scene& scene) { SceneValidator(scene.source_file).check(scene); }

}  // namespace shadowlab
