// The World, Light space and PPLS views: the scene, the camera frustum, the method's map volume and
// its step geometry, all carried into one space by the method's own frames. The chosen step's
// geometry is drawn bright; what earlier steps built stays, dimmed. A geometric technique has no
// map and no light spaces: the World view shows its steps (silhouette edges thick on the meshes,
// extruded quads and caps translucent, vertices at infinity drawn a scene's length away).
#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_inverse.hpp>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include "views/view_parts.hpp"

namespace shadowlab {
namespace {

const glm::dvec3 kHighlight{1.0, 0.85, 0.1}, kEarlier{0.55, 0.62, 0.78}, kFrustum{1.0, 1.0, 1.0},
    kMapVolume{0.3, 0.9, 1.0}, kLeftOut{1.0, 0.2, 0.8}, kCasterBox{0.95, 0.55, 0.2}, kReceiverBox{0.4, 0.85, 0.4};

Space space_of(ViewKind view) {
    return view == ViewKind::world ? Space::world : view == ViewKind::light ? Space::light : Space::ppls;
}

// World -> `space`, as the method defined it; nullopt when the method has no such space.
std::optional<glm::dmat4> frame(const Inspection& in, Space space) {
    if (space == Space::world) return glm::dmat4(1.0);
    if (space == Space::view && !in.trace.frame(space)) return in.scene.camera.view_matrix();
    return in.trace.frame(space);
}

// A linear map's volume: its cube [0,1]^3 carried back to the world (paraboloids have none).
Frustum linear_map_volume(const ShadowMap& map) {
    const glm::dmat4 inverse = glm::inverse(map.world_to_uvz);
    Frustum f{};
    const double corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int i = 0; i < 8; ++i) {
        const glm::dvec4 h = inverse * glm::dvec4(corner[i % 4][0], corner[i % 4][1], i < 4 ? 0.0 : 1.0, 1.0);
        f.corners[i] = glm::dvec3(h) / h.w;
    }
    return f;
}

void add(vtkRenderer* renderer, const Placed& placed, const glm::dvec3& colour, double width, double opacity = 1.0) {
    auto actor = actor_for(placed, colour);
    actor->GetProperty()->SetLineWidth(static_cast<float>(width));
    actor->GetProperty()->SetPointSize(static_cast<float>(2 * width));
    actor->GetProperty()->SetOpacity(opacity);
    actor->GetProperty()->SetAmbient(placed.data->GetNumberOfPolys() > 0 ? 0.3 : 1.0);
    renderer->AddActor(actor);
}

// The steps up to the chosen one, each in its own space carried into the view's.
void add_steps(vtkRenderer* renderer, const Inspection& in, const glm::dmat4& to_view, const std::string& chosen,
               ViewReport& report) {
    const std::vector<Step>& steps = in.trace.steps();
    const size_t last = chosen.empty() ? steps.size() - 1
                                       : static_cast<size_t>(std::find_if(steps.begin(), steps.end(),
                                                                          [&](const Step& s) { return s.id == chosen; }) -
                                                             steps.begin());
    for (size_t i = 0; i <= last && i < steps.size(); ++i) {
        const auto step_frame = frame(in, steps[i].space);
        if (!step_frame) continue;
        const glm::dmat4 to = to_view * glm::inverse(*step_frame);
        const bool highlight = i == last;
        for (const NamedGeometry& g : steps[i].geometry) {
            const Placed placed = geometry_polydata(g.geometry, to, in.inputs.scene_bounds.diagonal());
            const bool solid = std::holds_alternative<ConvexPolyhedron>(g.geometry) ||
                               std::holds_alternative<PolygonSet>(g.geometry);
            // Edges (silhouettes) stay thick after their step: they lie on the meshes' own edges.
            const double width = std::holds_alternative<SegmentSet>(g.geometry) ? (highlight ? 5.0 : 3.0)
                                                                                 : (highlight ? 3.0 : 1.0);
            add(renderer, placed, highlight ? kHighlight : kEarlier, width, solid ? 0.3 : 1.0);
            if (highlight && placed.dropped)
                report.notes.push_back(steps[i].id + "/" + g.name + ": " + std::to_string(placed.dropped) +
                                       " primitives at or behind w = 0 not drawn");
        }
    }
}

// Every linear map's volume (a cascade's maps side by side); a paraboloid's is named instead.
void add_map_volumes(vtkRenderer* renderer, const ShadowSetup& setup, const glm::dmat4& to_view, ViewReport& report) {
    for (const ShadowMap& map : setup.maps)
        if (map.projection == Projection::paraboloid)
            report.notes.push_back("a paraboloid map has no box-shaped volume: not drawn");
        else
            add(renderer, geometry_polydata(linear_map_volume(map), to_view), kMapVolume, 2.0);
}

// Caster and receiver box corners: those the map leaves outside [0,1]^3 in their own colour.
// Returns how many were left out.
size_t add_input_points(vtkRenderer* renderer, const Inspection& in, const glm::dmat4& to_view) {
    std::vector<glm::dvec3> inside, left_out;
    for (const auto& points : {in.inputs.caster_points(), in.inputs.receiver_points()})
        for (const glm::dvec3& p : points) {
            const std::optional<MapPoint> at = map_point(in.setup, p);
            const bool covered = at && glm::all(glm::greaterThanEqual(at->uvz(), glm::dvec3(-1e-6))) &&
                                 glm::all(glm::lessThanEqual(at->uvz(), glm::dvec3(1.0 + 1e-6)));
            (covered ? inside : left_out).push_back(p);
        }
    add(renderer, points_polydata(inside, to_view), kFrustum, 1.5);
    add(renderer, points_polydata(left_out, to_view), kLeftOut, 2.5);
    return left_out.size();
}

// The light in the world: rays from its side toward the scene's centre (directional), or from
// its position (spot, point), with the light's end marked.
void add_light(vtkRenderer* renderer, const Scene& scene) {
    const Aabb bounds = scene.bounds();
    const glm::dvec3 centre = 0.5 * (bounds.min + bounds.max);
    const glm::dvec3 from = scene.light.is_directional() ? centre - 0.6 * bounds.diagonal() * scene.light.direction
                                                         : scene.light.position;
    add(renderer, segments_polydata({{from, centre}}, glm::dmat4(1.0)), kHighlight, 3.0);
    add(renderer, points_polydata({from}, glm::dmat4(1.0)), kHighlight, 6.0);
}

void add_boxes(vtkRenderer* renderer, const std::vector<Aabb>& boxes, const glm::dmat4& to_view, const glm::dvec3& colour) {
    for (const Aabb& box : boxes) add(renderer, geometry_polydata(box, to_view), colour, 1.0, 0.6);
}

// What the camera frames: the scene in the world; in the light spaces the intersection body (what
// the method works on; the scene's bounds for methods without one), since points near w = 0 fly
// off toward infinity there and a warp's map volume reaches far beyond the scene.
Aabb framed_region(const Inspection& in, ViewKind view, const glm::dmat4& to_view) {
    if (view == ViewKind::world) return in.scene.bounds();
    const Step* body_step = in.trace.find("body");
    const auto* body = body_step && !body_step->geometry.empty()
                           ? std::get_if<ConvexPolyhedron>(&body_step->geometry.front().geometry) : nullptr;
    const auto corners = in.scene.bounds().corners();
    const std::vector<glm::dvec3> points = body ? body->vertices : std::vector<glm::dvec3>(corners.begin(), corners.end());
    Aabb box;
    for (const glm::dvec3& p : points) {
        const glm::dvec4 h = to_view * glm::dvec4(p, 1.0);
        if (h.w > 0.0) box.extend(glm::dvec3(h) / h.w);
    }
    return box.empty() ? in.scene.bounds() : box;
}

// The world view from behind, above and beside the scene camera; the light spaces from the
// light's side (their +z runs with the light), slightly tilted to show depth.
void place_overview_camera(vtkRenderer* renderer, const Inspection& in, ViewKind view, const Aabb& region) {
    glm::dvec3 direction{0.25, 0.35, 1.0};
    if (view == ViewKind::world) {
        const glm::dvec3 d = in.scene.camera.view_direction();
        direction = d + glm::dvec3(0.0, -0.8, 0.0) + 0.6 * glm::normalize(glm::cross(d, glm::dvec3(0, 1, 0)));
    }
    direction = glm::normalize(direction);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(-direction.x, -direction.y, -direction.z);
    camera->SetViewUp(0.0, 1.0, 0.0);
    double bounds[6] = {region.min.x, region.max.x, region.min.y, region.max.y, region.min.z, region.max.z};
    renderer->ResetCamera(bounds);
    const glm::dvec3 centre = 0.5 * (region.min + region.max), reach = 4.0 * (region.max - region.min);
    double far_bounds[6] = {centre.x - reach.x, centre.x + reach.x, centre.y - reach.y,
                            centre.y + reach.y, centre.z - reach.z, centre.z + reach.z};
    renderer->ResetCameraClippingRange(far_bounds);
}

}  // namespace

ViewReport build_space_view(vtkRenderer* renderer, const Inspection& in, ViewKind view, const ViewOptions& options) {
    ViewReport report;
    renderer->SetBackground(0.12, 0.13, 0.16);
    const auto to_view = frame(in, space_of(view));
    if (!to_view) {
        add_caption(renderer, in.title() + ": no " + view_title(view) +
                                  (in.has_map() ? " (the method has no such space)"
                                                : " (a geometric technique: no light space, no map; see the World view)"));
        return report;
    }
    const Placed scene = triangles_polydata(in.triangles, std::vector<bool>(in.scene.objects.size(), true),
                                            object_colours(in.scene), *to_view);
    add(renderer, scene, glm::dvec3(1.0), 1.0, view == ViewKind::world ? 1.0 : 0.35);
    if (scene.dropped) report.notes.push_back(std::to_string(scene.dropped) + " scene triangles at or behind w = 0 not drawn");
    add(renderer, geometry_polydata(in.inputs.frustum, *to_view), kFrustum, 2.0);
    if (in.has_map()) add_map_volumes(renderer, in.setup, *to_view, report);
    if (view == ViewKind::world) {
        add_boxes(renderer, in.inputs.casters, *to_view, kCasterBox);
        add_boxes(renderer, in.inputs.receivers, *to_view, kReceiverBox);
        add_light(renderer, in.scene);
    }
    const size_t left_out = in.has_map() ? add_input_points(renderer, in, *to_view) : 0;
    add_steps(renderer, in, *to_view, options.step, report);
    place_overview_camera(renderer, in, view, framed_region(in, view, *to_view));
    const std::string step = !options.step.empty()      ? options.step
                             : in.trace.steps().empty() ? std::string("none recorded")
                                                        : in.trace.steps().back().id;
    const std::string legend = in.has_map() ? "white: camera frustum, cyan: the map's volume; box corners inside the map "
                                              "white, outside magenta (" + std::to_string(left_out) + ")"
                                            : "white: camera frustum; no map (a geometric technique)";
    add_caption(renderer, std::string(view_title(view)) + " — " + in.name() + ", step " + step +
                              " (yellow; earlier steps blue)\n" + legend);
    return report;
}

}  // namespace shadowlab
