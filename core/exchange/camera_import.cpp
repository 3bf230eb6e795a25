// An engine's view and projection as the scene's Camera. Both matrices are first brought to
// OpenGL's conventions, a right-handed eye space looking down -z and clip z / w in [-1, 1] from
// the near plane to the far one; there glm::perspective's closed forms give the camera back:
// P(1,1) = 1 / tan(fov / 2), P(0,0) = P(1,1) / aspect, P(2,2) = -(f + n) / (f - n),
// P(2,3) = -2 f n / (f - n), P(3,2) = -1 (row, column); or glm::ortho's, for a projection whose last
// row is (0, 0, 0, 1): P(1,1) = 1 / half height, P(0,0) = P(1,1) / aspect, P(2,2) = -2 / (f - n),
// P(2,3) = -(f + n) / (f - n).
#include "exchange/camera_import.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "limits.hpp"
#include "math/matrix.hpp"
#include "methods/engine_conventions.hpp"

namespace shadowlab {
namespace {

using Json = nlohmann::json;

// Entries a pinhole leaves 0 may differ from it by this share of their row's scale: the rounding
// of a matrix written in float, and no more (a TAA jitter of one pixel in 4K shifts by 2.6e-4).
constexpr double kZeroTolerance = 1e-5;

double entry(const glm::dmat4& m, int row, int column) { return m[column][row]; }

std::string shown(double value) {
    std::ostringstream out;
    out.precision(6);
    out << value;
    return out.str();
}

// ---- Reading ----

// Whether `name` holds `word`, in any case.
bool holds(std::string name, const std::string& word) {
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
    return name.find(word) != std::string::npos;
}

bool is_view_name(const std::string& name) { return holds(name, "view") && !holds(name, "proj"); }
bool is_projection_name(const std::string& name) { return holds(name, "proj") && !holds(name, "view"); }

EngineCamera parse_shader(const std::string& text, MatrixStorage storage, const std::string& file) {
    const std::vector<ShaderMatrix> matrices = shader_matrices(text, storage, file);
    const auto named = [&](bool (*is_named)(const std::string&)) {
        return std::count_if(matrices.begin(), matrices.end(), [&](const ShaderMatrix& m) { return is_named(m.name); });
    };
    if (named(is_view_name) != 1 || named(is_projection_name) != 1) {
        std::string found;
        for (const ShaderMatrix& m : matrices) found += (found.empty() ? "" : ", ") + (m.name.empty() ? "?" : m.name);
        refuse_matrix_text(file, "",
                           "expected one matrix named for the view (\"view\" without \"proj\": view, viewMatrix) and "
                           "one for the projection (\"proj\" without \"view\": projection, uProj); found: " +
                               (found.empty() ? "none" : found));
    }
    EngineCamera camera;
    for (const ShaderMatrix& m : matrices) {
        const std::string field = m.name + ", " + m.where;
        if (is_view_name(m.name)) camera.eye_from_world = m.matrix, camera.view_field = field;
        if (is_projection_name(m.name)) camera.clip_from_eye = m.matrix, camera.projection_field = field;
    }
    return camera;
}

EngineCamera parse_json(const std::string& text, MatrixStorage storage, const std::string& file) {
    const Json json = json_object(text, {"camera", "matrices", "tiles", "split_depths"}, file);
    if (!json.contains("camera") || !json["camera"].is_object())
        refuse_matrix_text(file, "camera", "expected {\"view\": V, \"projection\": P}");
    const Json& camera = json["camera"];
    for (const auto& item : camera.items())
        if (item.key() != "view" && item.key() != "projection")
            refuse_matrix_text(file, "camera." + item.key(), "unknown key; allowed: view, projection");
    for (const char* key : {"view", "projection"})
        if (!camera.contains(key)) refuse_matrix_text(file, std::string("camera.") + key, "missing");
    return {.eye_from_world = json_matrix(camera["view"], storage, file, "camera.view"),
            .clip_from_eye = json_matrix(camera["projection"], storage, file, "camera.projection"),
            .view_field = "camera.view",
            .projection_field = "camera.projection"};
}

// ---- Conversion to OpenGL's conventions ----

// Direct3D's left-handed eye space is the right-handed one mirrored in z: eye_lh = flip * eye_rh.
glm::dmat4 z_flip(const CameraConventions& c) {
    return c.looks_along == EyeForward::plus_z ? glm::dmat4(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, 1, 0, 0),
                                                            glm::dvec4(0, 0, -1, 0), glm::dvec4(0, 0, 0, 1))
                                               : glm::dmat4(1.0);
}

// The engine's clip space to OpenGL's: through the map space (u, v, d) of clip_conventions, whose v
// follows clip y up or against it, then x = 2u - 1, y = 2v - 1, z = 2d - 1 (each times w).
glm::dmat4 gl_clip_from_engine_clip(const CameraConventions& c) {
    const glm::dmat4 gl_clip_from_uvz = from_rows({2, 0, 0, -1}, {0, 2, 0, -1}, {0, 0, 2, -1}, {0, 0, 0, 1});
    return gl_clip_from_uvz *
           uvz_from_clip(
               {.depth = c.depth, .reversed_z = c.reversed_z, .v = c.y == ClipY::up ? TextureV::up : TextureV::down});
}

std::string set_other(const char* setting, const char* value) { return std::string("set ") + setting + "=" + value; }

// ---- The view: a rotation and a translation ----

void check_view(const glm::dmat4& eye_from_world, const CameraConventions& c, const std::string& file,
                const std::string& field) {
    if (is_singular(eye_from_world)) refuse_matrix_text(file, field, "singular matrix (determinant 0): no camera view");
    const glm::dvec4 last = row(eye_from_world, 3);
    if (glm::length(last - glm::dvec4(0, 0, 0, 1)) > kZeroTolerance)
        refuse_matrix_text(file, field,
                           "not a view: its last row is (" + shown(last.x) + ", " + shown(last.y) + ", " +
                               shown(last.z) + ", " + shown(last.w) + "), expected (0, 0, 0, 1)");
    const glm::dmat3 rotation(eye_from_world);
    const glm::dmat3 gram = glm::transpose(rotation) * rotation;
    double off = 0.0;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) off = std::max(off, std::abs(gram[a][b] - (a == b ? 1.0 : 0.0)));
    if (off > kZeroTolerance)
        refuse_matrix_text(
            file, field,
            "not a rigid view: its 3x3 part is skewed or scaled (R^T R differs from I by " + shown(off) + ")");
    if (glm::determinant(rotation) < 0.0)
        refuse_matrix_text(file, field,
                           "a mirror (determinant -1): the eye space is of the other hand; " +
                               (c.looks_along == EyeForward::minus_z ? set_other("looks_along", "plus_z")
                                                                     : set_other("looks_along", "minus_z")));
}

// ---- The projection: a symmetric perspective or orthographic one ----

// The entry (row, column) that should be 0 and is not beyond `scale`'s share, named with `problem`.
void expect_zero(const glm::dmat4& p, int r, int c, double scale, const std::string& problem, const std::string& file,
                 const std::string& field) {
    if (std::abs(entry(p, r, c)) > kZeroTolerance * scale)
        refuse_matrix_text(file, field,
                           problem + " (entry (" + std::to_string(r) + ", " + std::to_string(c) + ") = " +
                               shown(entry(p, r, c)) + ", row and column as applied to column vectors): unsupported");
}

// An orthographic projection's w does not depend on the eye's depth: its last row is (0, 0, 0, w).
bool is_orthographic(const glm::dmat4& gl_clip_from_eye) {
    const glm::dvec4 w_row = row(gl_clip_from_eye, 3);
    return std::abs(w_row.z) <= kZeroTolerance * glm::length(w_row);
}

// The projection scaled so that w = -z_eye (a pinhole) or w = 1 (orthographic: a homogeneous matrix
// projects alike at any positive scale), its w row checked.
glm::dmat4 normalized_w(const glm::dmat4& gl_clip_from_eye, const CameraConventions& c, const std::string& file,
                        const std::string& field) {
    const glm::dvec4 w_row = row(gl_clip_from_eye, 3);
    if (is_orthographic(gl_clip_from_eye)) {
        const glm::dmat4 p = gl_clip_from_eye / w_row.w;
        expect_zero(p, 3, 0, 1.0, "not an orthographic projection's w", file, field);
        expect_zero(p, 3, 1, 1.0, "not an orthographic projection's w", file, field);
        return p;
    }
    if (w_row.z > 0.0)
        refuse_matrix_text(file, field,
                           "w = +z in eye space: the camera looks the other way; " +
                               (c.looks_along == EyeForward::minus_z ? set_other("looks_along", "plus_z")
                                                                     : set_other("looks_along", "minus_z")));
    const glm::dmat4 p = gl_clip_from_eye / -w_row.z;
    expect_zero(p, 3, 0, 1.0, "not a pinhole's w", file, field);
    expect_zero(p, 3, 1, 1.0, "not a pinhole's w", file, field);
    expect_zero(p, 3, 3, 1.0, "not a pinhole's w", file, field);
    return p;
}

// The projection normalized (normalized_w), its shape checked: x and y scaled only, centred, and a
// depth that depends on the eye's depth alone. A pinhole's centre is in column 2 (x / w shifted by
// z / w), an orthographic one's in column 3.
glm::dmat4 normalized_projection(const glm::dmat4& gl_clip_from_eye, const CameraConventions& c,
                                 const std::string& file, const std::string& field) {
    if (is_singular(gl_clip_from_eye))
        refuse_matrix_text(file, field, "singular matrix (determinant 0): no camera projection");
    const glm::dmat4 p = normalized_w(gl_clip_from_eye, c, file, field);
    const bool orthographic = is_orthographic(gl_clip_from_eye);
    const double x_scale = std::abs(entry(p, 0, 0)), y_scale = std::abs(entry(p, 1, 1));
    const int centre = orthographic ? 3 : 2, other = orthographic ? 2 : 3;
    const std::string off_centre = orthographic ? "off-centre view box" : "asymmetric (off-centre) frustum";
    expect_zero(p, 0, 1, x_scale, "skewed: x mixes in y", file, field);
    expect_zero(p, 1, 0, y_scale, "skewed: y mixes in x", file, field);
    expect_zero(p, 0, centre, x_scale, off_centre, file, field);
    expect_zero(p, 1, centre, y_scale, off_centre, file, field);
    expect_zero(p, 0, other, x_scale, orthographic ? "oblique: x depends on depth" : "x shifted in clip space", file,
                field);
    expect_zero(p, 1, other, y_scale, orthographic ? "oblique: y depends on depth" : "y shifted in clip space", file,
                field);
    const double depth_scale = std::max(std::abs(entry(p, 2, 2)), std::abs(entry(p, 2, 3)));
    expect_zero(p, 2, 0, depth_scale, "oblique near plane: depth depends on x", file, field);
    expect_zero(p, 2, 1, depth_scale, "oblique near plane: depth depends on y", file, field);
    if (entry(p, 1, 1) < 0.0)
        refuse_matrix_text(file, field,
                           "the image is upside down (entry (1, 1) < 0): clip y runs the other way; " +
                               (c.y == ClipY::up ? set_other("clip_y", "down") : set_other("clip_y", "up")));
    if (entry(p, 0, 0) < 0.0)
        refuse_matrix_text(file, field, "the image is mirrored left to right (entry (0, 0) < 0): unsupported");
    return p;
}

// Near and far, checked within the scene's limits.
std::pair<double, double> checked_near_and_far(double near, double far, const std::string& hint,
                                               const std::string& file, const std::string& field) {
    if (!(near > 0.0 && far > near))
        refuse_matrix_text(file, field,
                           "its depth puts the near plane at " + shown(near) + " and the far one at " + shown(far) +
                               ": not 0 < near < far; check " + hint);
    if (!limits::within(limits::length, near) || !limits::within(limits::length, far) ||
        far > limits::far_over_near_max * near)
        refuse_matrix_text(file, field,
                           "near " + shown(near) + " and far " + shown(far) + " must lie in " +
                               limits::shown(limits::length) + ", far / near at most " +
                               limits::shown(limits::far_over_near_max));
    return {near, far};
}

// A pinhole's near and far from P(2,2) = c, P(2,3) = d: n = d / (c - 1), f = d / (c + 1).
// c + 1 = -2 n / (f - n), so far / near beyond the limit shows as c within 2 / limit of -1.
std::pair<double, double> perspective_near_and_far(const glm::dmat4& p, const std::string& file,
                                                   const std::string& field) {
    const double c = entry(p, 2, 2), d = entry(p, 2, 3);
    if (std::abs(c + 1.0) < 2.0 / limits::far_over_near_max)
        refuse_matrix_text(file, field,
                           "the far plane lies at infinity (or far / near beyond " +
                               limits::shown(limits::far_over_near_max) +
                               "): unsupported, the scene's camera needs a finite far plane");
    return checked_near_and_far(d / (c - 1.0), d / (c + 1.0), "clip_depth and reversed_z", file, field);
}

// An orthographic camera's near and far from P(2,2) = c = -2 / (f - n), P(2,3) = d = -(f + n) / (f - n)
// (glm::ortho): n = (d + 1) / c, f = (d - 1) / c.
std::pair<double, double> orthographic_near_and_far(const glm::dmat4& p, const std::string& file,
                                                    const std::string& field) {
    const double c = entry(p, 2, 2), d = entry(p, 2, 3);
    return checked_near_and_far((d + 1.0) / c, (d - 1.0) / c, "clip_depth, reversed_z and looks_along", file, field);
}

}  // namespace

std::vector<SettingSpec> camera_convention_settings() {
    return {storage_setting(),
            clip_depth_setting(),
            reversed_z_setting(),
            {.name = "clip_y",
             .description = "which way clip y runs: up the image (OpenGL, Direct3D) or down (Vulkan)",
             .default_value = "up",
             .choices = {"up", "down"}},
            {.name = "looks_along",
             .description = "the eye space: minus_z (right-handed: OpenGL, Vulkan, glm) or plus_z (left-handed: "
                            "Direct3D's LookAtLH and PerspectiveFovLH)",
             .default_value = "minus_z",
             .choices = {"minus_z", "plus_z"}}};
}

CameraConventions camera_conventions_from(const std::map<std::string, std::string>& overrides) {
    const Settings s = resolve_settings("camera conventions", camera_convention_settings(), overrides);
    return {.storage = storage_of(s),
            .depth = clip_depth_of(s),
            .reversed_z = reversed_z_of(s),
            .y = s.choice("clip_y") == "down" ? ClipY::down : ClipY::up,
            .looks_along = s.choice("looks_along") == "plus_z" ? EyeForward::plus_z : EyeForward::minus_z};
}

EngineCamera parse_engine_camera(const std::string& text, MatrixStorage storage, const std::string& file) {
    return is_json_text(text) ? parse_json(text, storage, file) : parse_shader(text, storage, file);
}

Camera camera_from_engine(const EngineCamera& engine, const CameraConventions& conventions, const Aabb& scene_bounds,
                          const std::string& file) {
    const glm::dmat4 flip = z_flip(conventions);  // its own inverse
    const glm::dmat4 eye_from_world = flip * engine.eye_from_world;
    check_view(eye_from_world, conventions, file, engine.view_field);
    const glm::dmat4 gl_clip_from_eye = gl_clip_from_engine_clip(conventions) * engine.clip_from_eye * flip;
    const glm::dmat4 clip_from_eye =
        normalized_projection(gl_clip_from_eye, conventions, file, engine.projection_field);
    const bool orthographic = is_orthographic(gl_clip_from_eye);
    const auto [near, far] = orthographic ? orthographic_near_and_far(clip_from_eye, file, engine.projection_field)
                                          : perspective_near_and_far(clip_from_eye, file, engine.projection_field);

    // The eye's axes in world space are the rotation's rows; the eye sits where the view sends to 0.
    const glm::dmat3 rotation(eye_from_world);
    const glm::dvec3 position = -(glm::transpose(rotation) * glm::dvec3(eye_from_world[3]));
    const glm::dvec3 ahead = -glm::dvec3(row(eye_from_world, 2));
    const double to_centre = scene_bounds.empty() ? near : glm::length(scene_bounds.center() - position);
    const double aspect = entry(clip_from_eye, 1, 1) / entry(clip_from_eye, 0, 0);
    if (!limits::within(limits::aspect, aspect))
        refuse_matrix_text(file, engine.projection_field,
                           "aspect " + shown(aspect) + " is outside " + limits::shown(limits::aspect));
    return {.position = position,
            .target = position + std::max(to_centre, near) * ahead,
            .up = glm::dvec3(row(eye_from_world, 1)),
            .fov_y_deg =
                orthographic ? Camera{}.fov_y_deg : glm::degrees(2.0 * std::atan(1.0 / entry(clip_from_eye, 1, 1))),
            .aspect = aspect,
            .near = near,
            .far = far,
            .projection = orthographic ? CameraProjection::orthographic : CameraProjection::perspective,
            .half_height = orthographic ? 1.0 / entry(clip_from_eye, 1, 1) : Camera{}.half_height};
}

Camera import_camera(const std::string& file, const CameraConventions& conventions, const Aabb& scene_bounds) {
    return camera_from_engine(parse_engine_camera(read_matrix_file(file), conventions.storage, file), conventions,
                              scene_bounds, file);
}

}  // namespace shadowlab
