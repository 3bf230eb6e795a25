#include "methods/warp_common.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

#include "math/matrix.hpp"
#include "methods/focused.hpp"
#include "methods/light_fit.hpp"
#include "methods/map_fit.hpp"
#include "methods/step_figures.hpp"

namespace shadowlab {

std::optional<IntersectionBody> start_warp(const std::string& method, const ShadowInputs& in, const Settings& settings,
                                           ShadowSetup& setup, Trace* trace) {
    auto body = body_or_uniform(in, settings, setup, trace);
    if (body && !in.light.is_directional()) {
        fall_back_to_focused(
            Note{NoteKind::not_directional, method + " warps directional lights only; focused map used for this " +
                                                to_string(in.light.type) + " light"},
            in, *body, setup, trace);
        return std::nullopt;
    }
    return body;
}

namespace {

// Under an orthographic camera the view's post-perspective space is an affine image of the world: a
// warp that adapts the map to the camera's perspective (PSM's, LiSPSM's with n = infinity, TSM's
// trapezoid become a rectangle, XPSM's) has nothing to do. Names the fallback; true when taken.
bool falls_back_for_orthographic(const std::string& method, const ShadowInputs& in, const IntersectionBody& body,
                                 ShadowSetup& setup, Trace* trace) {
    if (!in.camera.is_orthographic()) return false;
    fall_back_to_focused(Note{NoteKind::orthographic_camera,
                              method + " warps a perspective view; the camera is orthographic: nothing to warp, "
                                       "focused map used"},
                         in, body, setup, trace);
    return true;
}

}  // namespace

std::optional<IntersectionBody> start_perspective_warp(const std::string& method, const ShadowInputs& in,
                                                       const Settings& settings, ShadowSetup& setup, Trace* trace) {
    auto body = start_warp(method, in, settings, setup, trace);
    if (body && falls_back_for_orthographic(method, in, *body, setup, trace)) return std::nullopt;
    return body;
}

std::optional<WarpRegion> start_warp_in_reach(const std::string& method, const ShadowInputs& in,
                                              const Settings& settings, ShadowSetup& setup, Trace* trace) {
    auto body = body_or_uniform(in, settings, setup, trace);
    if (!body || falls_back_for_orthographic(method, in, *body, setup, trace)) return std::nullopt;
    if (in.light.type != LightType::spot) return WarpRegion{*body, body->body.vertices};
    std::vector<glm::dvec3> reach = spot_reach(in.light, body->body, trace);
    if (reach.empty()) {
        fall_back_to_focused(Note{NoteKind::view_outside_cone, "B misses the spot's cone; focused map used"}, in, *body,
                             setup, trace);
        return std::nullopt;
    }
    return WarpRegion{std::move(*body), std::move(reach)};
}

namespace {

// A pyramid of kConeSides sides circumscribing the spot's cone, apex at the light: the region it
// holds is at most 1 / cos(π / kConeSides) - 1 = 2% wider than the cone, so a map fitted to it in any
// orientation (a warp's axes need not be the focused map's) holds little the spot does not light.
constexpr int kConeSides = 16;

struct ConePyramid {
    std::vector<Plane> sides;                 // outward normals, through the light
    std::vector<glm::dvec3> edge_directions;  // world, unit: the edges leaving the apex
};

ConePyramid cone_pyramid(const Light& spot) {
    const glm::dvec3 axis = glm::normalize(spot.direction);
    const glm::dvec3 x = glm::normalize(glm::cross(stable_up_hint(axis), axis)), y = glm::cross(axis, x);
    const double half_angle = glm::radians(spot.cone_deg / 2), step = 2 * glm::pi<double>() / kConeSides;
    ConePyramid pyramid;
    for (int i = 0; i < kConeSides; ++i) {
        // Side i touches the cone along the ray at azimuth i step: its normal is that ray's outward normal.
        const glm::dvec3 radial = std::cos(i * step) * x + std::sin(i * step) * y;
        const glm::dvec3 outward = std::cos(half_angle) * radial - std::sin(half_angle) * axis;
        pyramid.sides.push_back(Plane::through(spot.position, outward));
        // Sides i and i + 1 meet at azimuth (i + ½) step, 1 / cos(step / 2) farther out than the cone.
        const glm::dvec3 between = std::cos((i + 0.5) * step) * x + std::sin((i + 0.5) * step) * y;
        pyramid.edge_directions.push_back(glm::normalize(axis + std::tan(half_angle) / std::cos(step / 2) * between));
    }
    return pyramid;
}

// `body` cut by each plane in turn (kept: their insides), and the cut's vertices but the light's
// position: a warp's regions have it as their apex when the light stands inside the scene.
struct Cut {
    ConvexPolyhedron poly;
    std::vector<glm::dvec3> vertices_off_light;
};

Cut cut(const ConvexPolyhedron& body, const std::vector<Plane>& planes, const glm::dvec3& light_position) {
    const double size = body.bounds().diagonal();
    Cut result{body, {}};
    for (const Plane& plane : planes)
        if (!result.poly.empty()) result.poly = clip(result.poly, plane, 1e-10 * size);
    if (!result.poly.empty())
        for (const glm::dvec3& v : result.poly.vertices)
            if (glm::distance(v, light_position) > 1e-9 * size) result.vertices_off_light.push_back(v);
    return result;
}

}  // namespace

std::vector<glm::dvec3> spot_reach(const Light& spot, const ConvexPolyhedron& body, Trace* trace) {
    const ConePyramid pyramid = cone_pyramid(spot);
    const Cut reach = cut(body, pyramid.sides, spot.position);
    const std::vector<glm::dvec3>& points = reach.vertices_off_light;
    record(trace, [&](Trace& t) {
        Step& step = t.add("spot-reach", "Spot's reach",
                           "B ∩ a 16-sided pyramid around the cone: only what the "
                           "spot lights needs texels",
                           Space::world)
                         .value("cone_deg", spot.cone_deg)
                         .value("vertices", double(points.size()));
        // The pyramid's edges down to the reach's farthest depth along the axis: its base holds the reach.
        double far = 0.0;
        for (const glm::dvec3& p : points) far = std::max(far, glm::dot(p - spot.position, spot.direction));
        SegmentSet edges;
        for (const glm::dvec3& d : pyramid.edge_directions)
            edges.segments.push_back({spot.position, spot.position + far / glm::dot(d, spot.direction) * d});
        step.shape("cone pyramid", edges, Role::light).shape("spot", Label{spot.position, "spot"}, Role::light);
        if (!reach.poly.empty())
            step.shape("B ∩ pyramid", reach.poly, Role::focus);
        else
            step.shape("B", body, Role::focus).shape("empty label", Label{body.centroid(), "B misses the cone"});
    });
    return points;
}

std::vector<glm::dvec3> body_within_frustum(const ConvexPolyhedron& body, const glm::dmat4& world_to_uvz,
                                            const glm::dvec3& light_position) {
    // Each bound is a homogeneous plane a · (p, 1) <= 0 of the map's rows: -w, -u w, u w - w, -v w, v w - w.
    const glm::dvec4 u = row(world_to_uvz, 0), v = row(world_to_uvz, 1), w = row(world_to_uvz, 3);
    std::vector<Plane> bounds;
    for (const glm::dvec4& a : {-w, -u, u - w, -v, v - w})
        if (const double length = glm::length(glm::dvec3(a)); length > 0.0)
            bounds.push_back({glm::dvec3(a) / length, a.w / length});
    return cut(body, bounds, light_position).vertices_off_light;
}

glm::dvec3 light_ray_at(const Light& light, const glm::dvec3& p) {
    return light.is_directional() ? light.direction : glm::normalize(p - light.position);
}

void fall_back_to_focused(Note reason, const ShadowInputs& in, const IntersectionBody& body, ShadowSetup& setup,
                          Trace* trace) {
    add_fallback(setup, std::move(reason));
    fit_focused(in, body, setup, trace);
}

namespace {

DepthRange view_depths(const Camera& camera, const std::vector<glm::dvec3>& points) {
    DepthRange range{INFINITY, -INFINITY};
    for (const glm::dvec3& p : points) {
        const double depth = glm::dot(p - camera.position, camera.view_direction());
        range.near = std::min(range.near, depth);
        range.far = std::max(range.far, depth);
    }
    return range;
}

}  // namespace

DepthRange seen_receiver_depths(const ShadowInputs& in, const IntersectionBody& body) {
    if (in.visible_depths && !in.visible_depths->empty()) return *in.visible_depths;
    const DepthRange visible = view_depths(in.camera, body.visible.vertices);
    const DepthRange receivers = view_depths(in.camera, in.receiver_points());
    DepthRange seen{std::max({visible.near, receivers.near, in.camera.near}),
                    std::min({visible.far, receivers.far, in.camera.far})};
    if (seen.empty()) seen = {std::max(visible.near, in.camera.near), std::min(visible.far, in.camera.far)};
    return seen;
}

bool is_perspective_warp(const std::string& method) {
    return method == "psm" || method == "lispsm" || method == "tsm" || method == "xpsm";
}

std::string warp_choices(const Trace& trace) {
    struct Choice {
        const char* step;
        const char* value;
    };
    static constexpr Choice kChoices[] = {{"n-opt", "z_n"},
                                          {"n-opt", "z_f"},
                                          {"n-opt", "n"},  // lispsm
                                          {"psm-virtual-camera", "near"},
                                          {"psm-virtual-camera", "far"},
                                          {"psm-virtual-camera", "slide"},
                                          {"tsm-centre-line", "near"},
                                          {"tsm-centre-line", "far"},
                                          {"tsm-focus-80", "eta"},
                                          {"xpsm-7", "lengthP"},
                                          {"xpsm-5", "maxLengthP"}};
    std::string text;
    for (const Choice& choice : kChoices)
        if (const Step* step = trace.find(choice.step))
            for (const NamedValue& v : step->values)
                if (v.name == choice.value && std::holds_alternative<double>(v.value))
                    text += (text.empty() ? "" : ", ") + v.name + " = " + label_number(std::get<double>(v.value));
    return text;
}

std::vector<glm::dvec3> corners_within(const std::vector<Aabb>& boxes, const Aabb& region) {
    std::vector<glm::dvec3> points;
    for (const Aabb& b : boxes) {
        const Aabb cut{glm::max(b.min, region.min), glm::min(b.max, region.max)};
        if (cut.empty()) continue;
        for (const glm::dvec3& c : cut.corners()) points.push_back(c);
    }
    return points;
}

ProjectedPoints project(const std::vector<glm::dvec3>& points, const glm::dmat4& m, double min_w) {
    ProjectedPoints out;
    out.points.reserve(points.size());
    for (const glm::dvec3& p : points) {
        const glm::dvec4 h = m * glm::dvec4(p, 1.0);
        if (h.w < min_w)
            ++out.left_out;
        else
            out.points.push_back(glm::dvec3(h) / h.w);
    }
    return out;
}

}  // namespace shadowlab
