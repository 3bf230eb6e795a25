#include "scene/scene_validation.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "limits.hpp"
#include "math/normalize.hpp"
#include "scene/scene_error.hpp"

namespace shadowlab {
namespace {

constexpr double kMinLength = 1e-12;     // camera target closer to position counts as equal
constexpr double kMinSineToView = 1e-6;  // camera up closer to the view direction is parallel

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

    // Only the fields the object's shape uses.
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

}  // namespace

std::string join(const std::vector<std::string>& items) {
    std::string out;
    for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
    return out;
}

// "three numbers", "a positive number", "two finite numbers".
std::string count_of(std::size_t count, const std::string& adjective) {
    static const char* const words[] = {"no", "a", "two", "three"};
    const std::string word = count < 4 ? words[count] : std::to_string(count);
    return word + (adjective.empty() ? "" : " " + adjective) + (count == 1 ? " number" : " numbers");
}

void validate_scene(const Scene& scene) { SceneValidator(scene.source_file).check(scene); }

}  // namespace shadowlab
