// Focused shadow map: the orthographic light projection fit, in light space, to the intersection
// body B = hull(V ∪ light) ∩ S, V = view frustum ∩ S (Wimmer and Scherzer; Ogre's
// FocusedShadowCameraSetup). Only what can shadow the visible part of the scene gets texels.
#include "methods/focused.hpp"

#include "geometry/intersection_body.hpp"
#include "methods/map_fit.hpp"
#include "methods/step_figures.hpp"
#include "methods/uniform.hpp"

namespace shadowlab {

const SettingSpec& body_kernel_setting() {
    static const SettingSpec spec{"kernel",
                                  "intersection-body geometry: our float clipper (fast), CGAL epick, or CGAL "
                                  "epeck (exact, slowest)",
                                  "float",
                                  0,
                                  0,
                                  {"float", "epick", "epeck"}};
    return spec;
}

IntersectionBody focus_body(const ShadowInputs& in, const Settings& settings, Trace* trace) {
    const BodyKernel kernel = *body_kernel_from_string(settings.choice("kernel"));
    IntersectionBody body = intersection_body({in.frustum, in.scene_bounds, in.light.homogeneous()}, kernel);
    record(trace, [&](Trace& t) {
        Step& inputs = t.add("frustum", "View frustum and scene bounds",
                             "the camera's frustum F and the scene's bounds S", Space::world)
                           .shape("F", in.frustum, Role::view)
                           .shape("S", in.scene_bounds);
        // The receivers meeting F and the casters that can shadow them (none when F misses the scene).
        if (const auto points = in.receiver_points(); !points.empty())
            inputs.shape("receivers", PointSet{points}, Role::receivers);
        if (const auto points = in.caster_points(); !points.empty())
            inputs.shape("casters", PointSet{points}, Role::casters);
        Step& visible =
            t.add("visible", "Visible region V", "V = F ∩ S", Space::world).value("volume", body.visible.volume());
        if (!body.visible.empty())
            visible.shape("V", body.visible);
        else
            visible.shape("F", in.frustum, Role::view).shape("V label", Label{in.camera.position, "V empty"});
        Step& hull =
            t.add("body", "Intersection body B", "B = hull(V ∪ light) ∩ S: every point that can shadow V", Space::world)
                .value("kernel", std::string(to_string(kernel)))
                .value("volume", body.body.volume())
                .value("vertices", double(body.body.vertices.size()))
                .value("faces", double(body.body.faces.size()));
        if (!body.body.empty()) hull.shape("B", body.body, Role::focus);
        const glm::dvec3 aim = body.body.empty() ? in.scene_bounds.center() : body.body.centroid();
        draw_light(hull, in.light, aim, 0.25 * in.scene_bounds.diagonal());
    });
    return body;
}

std::optional<IntersectionBody> body_or_uniform(const ShadowInputs& in, const Settings& settings, ShadowSetup& setup,
                                                Trace* trace) {
    IntersectionBody body = focus_body(in, settings, trace);
    if (!body.body.empty()) return body;
    add_fallback(setup, Note{NoteKind::empty_body, "the view frustum does not meet the scene; uniform map used"});
    fit_uniform(in, setup, trace);
    return std::nullopt;
}

ShadowSetup compute_focused(const ShadowInputs& in, const Settings& settings, Trace* trace) {
    ShadowSetup setup;
    if (const auto body = body_or_uniform(in, settings, setup, trace)) fit_focused(in, *body, setup, trace);
    return setup;
}

void fit_focused(const ShadowInputs& in, const IntersectionBody& body, ShadowSetup& setup, Trace* trace) {
    // y along the view direction: the frustum's axis of symmetry lies along the map's v axis.
    fit_map(in, {&body.body.vertices, in.camera.view_direction(), body.body.centroid()}, setup, trace);
    record_output(setup, body.body.vertices, trace);
}

}  // namespace shadowlab
