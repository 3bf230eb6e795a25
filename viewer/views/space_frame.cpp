// The space a World, Light space or PPLS view draws in, the region its camera frames there, and the
// light's and the camera's directions carried into it (the presets look along them).
#include <algorithm>
#include <variant>

#include <glm/gtc/matrix_inverse.hpp>

#include "maps/projection_kind.hpp"
#include "views/space_parts.hpp"

namespace shadowlab {
namespace {

constexpr double kMargin = 0.15;      // of the region's extent, on every side
constexpr double kFlattest = 0.2;     // a margin is at least kMargin of this share of the widest extent
constexpr double kLightArrow = 0.25;  // the light arrow's length, as a share of the widest extent
constexpr double kContext = 10.0;     // context joins the region while it stays within this many times its size

std::optional<glm::dvec3> placed(const glm::dmat4& space_from_world, const glm::dvec3& world) {
    const glm::dvec4 h = space_from_world * glm::dvec4(world, 1.0);
    if (!(h.w > 0.0)) return std::nullopt;
    return glm::dvec3(h) / h.w;
}

// The box of the points in the space; empty when one lies at or behind w = 0 (then the space
// cannot frame them).
Aabb box_in_space(const glm::dmat4& space_from_world, const std::vector<glm::dvec3>& world_points) {
    Aabb box;
    for (const glm::dvec3& p : world_points) {
        const auto q = placed(space_from_world, p);
        if (!q) return {};
        box.extend(*q);
    }
    return box;
}

// The intersection body B, what the light-space methods work on; for a warp of a spot light, B cut
// to the spot's reach (part of B may lie behind the spot, where its light space has no place);
// nullopt without one.
std::optional<std::vector<glm::dvec3>> body_vertices(const Inspection& in) {
    for (const char* id : {"spot-reach", "body"})
        if (const Step* body = in.trace.find(id))
            for (const NamedGeometry& g : body->geometry)
                if (const auto* poly = std::get_if<ConvexPolyhedron>(&g.geometry)) return poly->vertices;
    return std::nullopt;
}

std::vector<glm::dvec3> scene_corners(const Inspection& in) {
    const auto corners = in.scene.bounds().corners();
    return {corners.begin(), corners.end()};
}

// What a light space frames: B, or the scene's bounds (a uniform map covers them all).
std::vector<glm::dvec3> body_points(const Inspection& in) { return body_vertices(in).value_or(scene_corners(in)); }

// What the World frames: B, or without one the casters (a geometric technique works on them), and
// the eye; a ground plane a hundred times wider than the objects would shrink them to dots.
std::vector<glm::dvec3> world_points(const Inspection& in) {
    std::vector<glm::dvec3> points = body_vertices(in).value_or(in.inputs.caster_points());
    if (points.empty()) points = scene_corners(in);
    points.push_back(in.scene.camera.position);
    return points;
}

// The corners of every linear map's volume.
std::vector<glm::dvec3> map_volume_corners(const ShadowSetup& setup) {
    std::vector<glm::dvec3> corners;
    for (const ShadowMap& map : setup.maps)
        if (projection_kind(map).projective())
            for (const glm::dvec3& c : map_volume(map).corners) corners.push_back(c);
    return corners;
}

double widest(const Aabb& box) {
    const glm::dvec3 e = box.extent();
    return std::max({e.x, e.y, e.z});
}

// The points that place a shape: its vertices, corners, ends; a polygon's vertices at infinity left out.
std::vector<glm::dvec3> shape_points(const TraceGeometry& geometry) {
    return std::visit(
        [](const auto& g) -> std::vector<glm::dvec3> {
            using G = std::decay_t<decltype(g)>;
            if constexpr (std::is_same_v<G, PointSet>)
                return g.points;
            else if constexpr (std::is_same_v<G, Aabb>)
                return {g.min, g.max};
            else if constexpr (std::is_same_v<G, ConvexPolyhedron>)
                return g.vertices;
            else if constexpr (std::is_same_v<G, Frustum>)
                return {g.corners.begin(), g.corners.end()};
            else if constexpr (std::is_same_v<G, SegmentSet>) {
                std::vector<glm::dvec3> ends;
                for (const auto& [a, b] : g.segments) ends.insert(ends.end(), {a, b});
                return ends;
            } else if constexpr (std::is_same_v<G, PolygonSet>) {
                std::vector<glm::dvec3> finite;
                for (const glm::dvec4& v : g.vertices)
                    if (v.w != 0.0) finite.push_back(glm::dvec3(v) / v.w);
                return finite;
            } else if constexpr (std::is_same_v<G, Arrow>)
                return {g.from, g.to};
            else if constexpr (std::is_same_v<G, AngleArc>)
                return {g.centre};
            else
                return {g.at};  // Label
        },
        geometry);
}

// `context` joined to the region when it can be framed and does not shrink the region to a dot.
void join(Aabb& region, const Aabb& context) {
    Aabb both = region;
    both.extend(context);
    if (!context.empty() && widest(both) <= kContext * widest(region)) region = both;
}

// What matters in the view's space: B and the eye in the World; B in Light space; the map's
// volume in PPLS, with B as the context it was cut from (XPSM's focus region is a small part of
// it). The chosen step's shapes join, so that its idea (the plane where w = 0, say) is in the
// picture, unless a warp stretches them toward w = 0 far beyond the region.
Aabb framed_region(const Inspection& in, Space space, const glm::dmat4& from_world, const Step* chosen) {
    const Aabb body = box_in_space(from_world, body_points(in));
    Aabb region = space == Space::world ? box_in_space(from_world, world_points(in)) : body;
    if (space == Space::ppls && in.has_map())
        if (const Aabb volumes = box_in_space(from_world, map_volume_corners(in.setup)); !volumes.empty()) {
            region = volumes;
            join(region, body);
        }
    if (!chosen || region.empty()) return region;
    const auto step_from_world = world_to(in, chosen->space);
    if (!step_from_world) return region;
    const glm::dmat4 from_step = from_world * glm::inverse(*step_from_world);
    for (const NamedGeometry& g : chosen->geometry) join(region, box_in_space(from_step, shape_points(g.geometry)));
    return region;
}

// A world direction as it runs through the space at `world` (the differential of the frame): in a
// warped space directions change from point to point, so they are taken where the region is.
glm::dvec3 direction_in_space(const glm::dmat4& from_world, const glm::dvec3& world, const glm::dvec3& direction,
                              double step) {
    const auto a = placed(from_world, world), b = placed(from_world, world + step * direction);
    if (!a || !b || glm::length(*b - *a) == 0.0) return glm::dvec3(0.0, 0.0, 1.0);
    return glm::normalize(*b - *a);
}

}  // namespace

std::optional<glm::dmat4> world_to(const Inspection& in, Space space) {
    if (space == Space::world) return glm::dmat4(1.0);
    if (space == Space::view && !in.trace.frame(space)) return in.scene.camera.view_matrix();
    return in.trace.frame(space);
}

double SpaceFrame::scale() const {
    glm::dvec3 e = region.extent();
    std::sort(&e[0], &e[0] + 3);
    return e[1];
}

Placement SpaceFrame::placement_from(const glm::dmat4& shape_from_world) const {
    return {.to_space = from_world * glm::inverse(shape_from_world), .clip = clip, .reach = 0.0, .head = arrow_head()};
}

bool unit_space_is_an_atlas(const Inspection& in, Space space) {
    return space == Space::unit && in.has_map() &&
           std::any_of(in.setup.maps.begin(), in.setup.maps.end(),
                       [](const ShadowMap& m) { return !projection_kind(m).projective() || !m.mask.empty(); });
}

std::optional<SpaceFrame> space_frame(const Inspection& in, Space space, const Step* chosen) {
    SpaceFrame frame{.space = space};
    auto from_world = world_to(in, frame.space);
    // A map with no warp has no post-perspective space of its own: its PPLS is the unit space.
    if (!from_world && frame.space == Space::ppls && in.has_map()) {
        frame.space = Space::unit;
        from_world = world_to(in, Space::unit);
    }
    if (!from_world) return std::nullopt;
    frame.from_world = *from_world;
    frame.atlas = unit_space_is_an_atlas(in, frame.space);
    frame.region =
        frame.atlas ? Aabb{glm::dvec3(0.0), glm::dvec3(1.0)} : framed_region(in, space, frame.from_world, chosen);
    if (frame.region.empty()) frame.region = box_in_space(frame.from_world, {glm::dvec3(0.0)});
    // A margin on every axis, at least a share of the widest so that a flat region keeps some depth.
    const glm::dvec3 extent = frame.region.extent();
    const double size = std::max(widest(frame.region), 1e-9);
    const glm::dvec3 margin = kMargin * glm::max(extent, glm::dvec3(kFlattest * size));
    frame.clip = {frame.region.min - margin, frame.region.max + margin};

    const glm::dvec4 centre_h = glm::inverse(frame.from_world) * glm::dvec4(frame.region.center(), 1.0);
    const glm::dvec3 centre = glm::dvec3(centre_h) / centre_h.w;
    const Scene& scene = in.scene;
    const glm::dvec3 light_world =
        scene.light.is_directional() ? scene.light.direction : glm::normalize(centre - scene.light.position);
    const double step = 1e-4 * std::max(scene.bounds().diagonal(), 1e-9);
    // The atlas is seen from in front of its (u, v) plane, as the Shadow map view shows the texture: u right, v up.
    frame.light =
        frame.atlas ? glm::dvec3(0.0, 0.0, -1.0) : direction_in_space(frame.from_world, centre, light_world, step);
    frame.view = frame.atlas ? glm::dvec3(0.0, 1.0, 0.0)
                             : direction_in_space(frame.from_world, centre, scene.camera.view_direction(), step);
    // The light arrow ends at the region's face toward the light, entering from beyond it.
    frame.light_to = frame.region.center() - 0.5 * glm::dot(glm::abs(frame.light), extent) * frame.light;
    frame.light_from = frame.light_to - kLightArrow * size * frame.light;
    frame.clip.extend(frame.light_from);
    return frame;
}

}  // namespace shadowlab
