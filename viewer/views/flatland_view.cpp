// The Flatland view (--view flatland): the plane of the view and the light (core/flatland), drawn
// in its own 2-D frame, the eye at the left and the view axis running right, the light coming from
// above: the camera's frustum, the intersection body B, each map's volume (a warp's frustum) and
// every k-th texel boundary of the maps as lines in the world, where Lloyd et al. 2008 show how a
// parameterization spends its texels along the view. Core computes the cross-section; this draws it.
#include <cstdio>

#include <vtkCamera.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include "flatland/flatland.hpp"
#include "render/map_overlay.hpp"
#include "views/space_parts.hpp"

namespace shadowlab {
namespace {

using Segments = std::vector<std::pair<glm::dvec3, glm::dvec3>>;

Segments segments_of(const std::vector<Polyline>& lines) {
    Segments segments;
    for (const Polyline& line : lines)
        for (size_t i = 0; i + 1 < line.size(); ++i) segments.emplace_back(line[i], line[i + 1]);
    return segments;
}

// The plane's frame as a space: (s, t) the picture's axes, the region the frame's rectangle.
SpaceFrame plane_frame(const Flatland& f) {
    const glm::dvec2 size = f.frame_max - f.frame_min;
    const double depth = 0.5 * std::min(size.x, size.y);  // so that arrow heads are sized by the shorter side
    SpaceFrame frame{.space = Space::world, .from_world = f.plane.plane_from_world()};
    frame.region.extend(glm::dvec3(f.frame_min, -depth));
    frame.region.extend(glm::dvec3(f.frame_max, depth));
    frame.clip = frame.region;
    return frame;
}

std::string ordinal(int k) {
    if (k == 1) return "every";
    const char* suffix = k % 10 == 1 && k % 100 != 11   ? "st"
                         : k % 10 == 2 && k % 100 != 12 ? "nd"
                         : k % 10 == 3 && k % 100 != 13 ? "rd"
                                                        : "th";
    return "every " + std::to_string(k) + suffix;
}

// Each map's boundaries of u (dimmed) and of v in the map's colour of the Camera view's overlay.
void draw_texel_lines(SpaceCanvas& canvas, const Flatland& f, const ShadowSetup& setup, const Placement& placement) {
    for (const MapSection& map : f.map_volumes)  // one per map the frame shows
        for (int axis : {0, 1}) {
            std::vector<Polyline> lines;
            for (const TexelLine& line : f.texel_lines)
                if (line.map == map.map && line.axis == axis) lines.push_back(line.points);
            const glm::dvec3 colour(kMapPalette[map.map % kMapPalette.size()]);
            const std::string whose = setup.maps.size() > 1 ? map_name(setup, map.map) + ": " : "";
            canvas.draw(segments_polydata(segments_of(lines), placement),
                        {.colour = axis == 0 ? dimmed(colour) : colour, .width = 1.0},
                        whose + (axis == 0 ? "u = i/" : "v = j/") + std::to_string(map.texels) + ", " +
                            ordinal(f.stride) + " boundary");
        }
}

void draw_sections(SpaceCanvas& canvas, const Flatland& f, const Placement& placement) {
    std::vector<Polyline> volumes;
    for (const MapSection& section : f.map_volumes)
        volumes.insert(volumes.end(), section.outline.begin(), section.outline.end());
    canvas.draw(segments_polydata(segments_of(volumes), placement),
                {.colour = role_style(Role::map).colour, .width = 2.0}, "map volume (a warp's frustum)");
    canvas.draw(segments_polydata(segments_of({closed_outline(f.body)}), placement),
                {.colour = role_style(Role::focus).colour, .width = 2.0}, "intersection body B");
    canvas.draw(segments_polydata(segments_of({closed_outline(f.frustum)}), placement),
                {.colour = role_style(Role::view).colour, .width = 2.0}, "camera frustum");
}

// The eye, the view axis V and the light's direction L, labelled.
void draw_eye_and_light(SpaceCanvas& canvas, const Flatland& f, const Light& light, const Placement& placement) {
    const glm::dvec3 eye = f.plane.eye, view_colour = role_style(Role::view).colour;
    const double length = 0.15 * (f.frame_max.x - f.frame_min.x);
    canvas.draw(geometry_polydata(Arrow{eye, eye + length * f.plane.along}, placement), {.colour = view_colour}, "");
    canvas.label(glm::dvec3(0.0), "eye", view_colour);
    canvas.label(glm::dvec3(length, 0.0, 0.0), "V", view_colour);
    const glm::dvec3 l = light_direction_at(light, eye), light_colour = role_style(Role::light).colour;
    // L's part in the plane, the arrow tucked into the frame's upper right corner.
    const glm::dvec2 in_plane = glm::normalize(glm::dvec2(glm::dot(l, f.plane.along), glm::dot(l, f.plane.across)));
    const glm::dvec2 corner = f.frame_max - 0.04 * (f.frame_max - f.frame_min);
    const glm::dvec2 tail = corner - length * glm::max(in_plane, glm::dvec2(0.0)), head = tail + length * in_plane;
    canvas.draw(geometry_polydata(Arrow{f.plane.world(tail), f.plane.world(head)}, placement),
                {.colour = light_colour, .width = 2.0}, "light");
    canvas.label(glm::dvec3(tail, 0.0), "L", light_colour);
}

void place_plane_camera(vtkRenderer* renderer, const Flatland& f) {
    const glm::dvec2 centre = 0.5 * (f.frame_min + f.frame_max), size = f.frame_max - f.frame_min;
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetPosition(centre.x, centre.y, 10.0 * std::max(size.x, size.y));
    camera->SetFocalPoint(centre.x, centre.y, 0.0);
    camera->SetViewUp(0, 1, 0);
    double aspect = size.x / size.y;
    if (const int* window = renderer->GetRenderWindow() ? renderer->GetRenderWindow()->GetSize() : nullptr;
        window && window[0] > 0 && window[1] > 0)
        aspect = static_cast<double>(window[0]) / window[1];
    constexpr double kRoomForLegendAndCaption = 1.25;
    camera->SetParallelScale(kRoomForLegendAndCaption * std::max(size.y / 2.0, size.x / (2.0 * aspect)));
    renderer->ResetCameraClippingRange();
}

// "41.2 per unit of view depth at z 0.5–4.6, 1.9 at z 17–21": the lines along the view near and far.
std::string axis_line_text(const Flatland& f) {
    const std::optional<AxisLineDensity> d = axis_line_density(f);
    if (!d) return "the view axis misses the scene";
    char text[160];
    std::snprintf(text, sizeof text, "%.3g per unit of view depth at z %.3g–%.3g, %.3g at z %.3g–%.3g", d->near_lines,
                  d->near.near, d->near.far, d->far_lines, d->far.near, d->far.far);
    return text;
}

ViewReport build_flatland_view(vtkRenderer* renderer, const Inspection& in, const ViewOptions&) {
    renderer->SetBackground(kSpaceBackground.r, kSpaceBackground.g, kSpaceBackground.b);
    if (!in.has_map()) {
        add_caption(renderer, in.title() + ": no shadow map, no texels to cut (Flatland shows a map's texels)");
        return {};
    }
    const Flatland f = flatland(in.inputs, in.setup, in.resolution);
    const SpaceFrame frame = plane_frame(f);
    const Placement placement = frame.placement_from(glm::dmat4(1.0));
    SpaceCanvas canvas(renderer, frame);
    canvas.draw(segments_polydata(scene_section(in.triangles, f.plane), placement), {.colour = glm::dvec3(0.55)},
                "the scene's surfaces");
    draw_texel_lines(canvas, f, in.setup, placement);
    draw_sections(canvas, f, placement);
    draw_eye_and_light(canvas, f, in.scene.light, placement);
    place_plane_camera(renderer, f);
    // Appended, not "literal" + string: GCC 12's false -Wrestrict (docs/ARCHITECTURE.md, "Habits").
    std::string caption("Flatland — ");
    caption.append(in.name()).append(": the plane of the view V and the light L, the eye at the left; ");
    caption.append(ordinal(f.stride)).append(" texel boundary of ").append(std::to_string(f.texels));
    caption.append(" drawn; along the view axis ").append(axis_line_text(f));
    if (!f.fallbacks.empty()) caption.append(" (").append(describe(f.fallbacks)).append(")");
    add_caption(renderer, caption);
    canvas.finish();
    ViewReport report;
    for (const Note& note : f.fallbacks) report.notes.push_back(describe(note));
    return report;
}

}  // namespace

View flatland_view() {
    return {.name = "flatland",
            .title = "Flatland",
            .prepare = {},  // computed from the setup as it is drawn
            .build = build_flatland_view,
            .choosers = {},
            .interaction = {.drag = ViewDrag::pans_image}};
}

}  // namespace shadowlab
