#include "planar/planar_technique.hpp"

#include <algorithm>

#include "math/stopwatch.hpp"
#include "methods/step_figures.hpp"
#include "planar/planar_projection.hpp"
#include "techniques/pixel_footprint.hpp"
#include "techniques/alpha_tested_limit.hpp"
#include "techniques/technique_figures.hpp"

namespace shadowlab {
namespace {

// "'a', 'b', 'c' and 4 more"
std::string some_names(const std::vector<std::string>& names) {
    std::string text;
    for (std::size_t i = 0; i < std::min<std::size_t>(names.size(), 3); ++i) text += (i ? ", '" : "'") + names[i] + "'";
    return names.size() > 3 ? text + " and " + std::to_string(names.size() - 3) + " more" : text;
}

struct Receivers {
    std::vector<ReceiverPlane> planes;
    std::vector<std::string> not_planes;  // receiving objects of other shapes: no planar shadow on them
};

Receivers receivers(const Scene& scene) {
    Receivers out;
    for (int o = 0; o < int(scene.objects.size()); ++o) {
        if (!scene.objects[o].receives) continue;
        if (scene.objects[o].shape != Shape::plane)
            out.not_planes.push_back(scene.objects[o].name);
        else if (std::optional<ReceiverPlane> r = receiver_plane(scene, o))
            out.planes.push_back(*r);
    }
    return out;
}

// The receiving plane object's own triangles, as the trace draws its plane.
PolygonSet plane_triangles(const WorldTriangles& triangles, int object) {
    PolygonSet set;
    for (std::size_t k = 0; k < triangles.triangles.size(); ++k) {
        if (triangles.object[k] != object) continue;
        std::vector<glm::dvec4> loop;
        for (int v : triangles.triangles[k]) loop.emplace_back(triangles.vertices[v], 1.0);
        set.add(loop);
    }
    return set;
}

void record_receiver(Trace* trace, const Scene& scene, const WorldTriangles& triangles, const ReceiverPlane& r,
                     const FlattenedCasters& f) {
    record(trace, [&](Trace& t) {
        const std::string name = scene.objects[r.object].name;
        const PolygonSet plane = plane_triangles(triangles, r.object);
        Aabb plane_bounds;
        for (const glm::dvec4& v : plane.vertices) plane_bounds.extend(glm::dvec3(v));
        t.add("planar.plane." + name, "Receiver plane '" + name + "'",
              "P = (n, d): n . x + d = 0, the light on its + side", Space::world)
            .value("P", r.plane)
            .shape("P", plane, Role::receivers)
            .shape(
                "n",
                Arrow{plane_bounds.center(), plane_bounds.center() + plane_bounds.diagonal() / 4 * glm::dvec3(r.plane)},
                Role::receivers)
            .shape("P label", Label{plane_bounds.center(), "P: '" + name + "'"}, Role::receivers);
        const double p_dot_l = glm::dot(r.plane, scene.light.homogeneous());
        draw_light(t.add("planar.light." + name, "Light",
                         "L = (position, 1), or (-direction, 0) for a directional light", Space::world)
                       .value("L", scene.light.homogeneous())
                       .value("P . L", p_dot_l)
                       .shape("P", plane, Role::receivers)
                       .shape("P . L label", Label{plane_bounds.center(), "P · L = " + label_number(p_dot_l)}),
                   scene.light, plane_bounds.center(), plane_bounds.diagonal() / 2);
        PolygonSet flattened;
        for (const HomogeneousPolygon& p : f.polygons) flattened.add(p);
        Step& matrix = t.add("planar.matrix." + name, "Projection matrix",
                             "M = (P . L) I - L P^T; x -> M x, divided by w, on the plane", Space::world)
                           .value("M", r.projection)
                           .value("flattened triangles", double(f.polygons.size()))
                           .value("triangles below the plane", double(f.below_plane))
                           .value("triangles beyond the light", double(f.beyond_light));
        if (flattened.polygons.empty())
            matrix.shape("shadow label", Label{plane_bounds.center(), "no caster above the plane"});
        else
            matrix.shape("shadow", std::move(flattened));
    });
}

std::vector<Note> limits(const Receivers& r, int below, int beyond) {
    std::vector<Note> out;
    if (!r.not_planes.empty())
        out.push_back(Note{NoteKind::not_planar_receiver,
                           some_names(r.not_planes) + " receive but are not planes: no shadow falls on them"});
    if (below > 0)
        out.push_back(Note{NoteKind::below_plane, std::to_string(below) +
                                                      " caster triangles reach below a receiving plane and "
                                                      "throw false shadows onto it"});
    if (beyond > 0)
        out.push_back(Note{NoteKind::beyond_light, std::to_string(beyond) +
                                                       " caster triangles reach as far from the plane as " +
                                                       "the light (w <= 0): clipped, else anti-shadows"});
    return out;
}

}  // namespace

GeometryResult compute_planar(const Scene& scene, const WorldTriangles& triangles, const ReferenceImage& image,
                              const Settings&, Trace* trace) {
    GeometryResult result;
    const std::size_t pixels = std::size_t(image.width) * image.height;
    result.shadowed.assign(pixels, 0);
    std::vector<int> fragments(pixels, 0);
    const CameraRays rays(scene.camera, image.width, image.height);
    const glm::dmat4 world_to_clip = scene.camera.infinite_projection_matrix() * scene.camera.view_matrix();
    const Receivers r = receivers(scene);
    int below = 0, beyond = 0;
    for (const ReceiverPlane& receiver : r.planes) {
        const Stopwatch setup;
        const FlattenedCasters f = flatten_casters(scene, triangles, receiver);
        result.setup_ms += setup.ms();
        record_receiver(trace, scene, triangles, receiver, f);
        below += f.below_plane;
        beyond += f.beyond_light;
        const Stopwatch raster;
        std::vector<PixelBox> boxes;
        for (const HomogeneousPolygon& p : f.polygons) boxes.push_back(pixel_footprint(world_to_clip, rays, p));
        const glm::dvec3 normal(receiver.plane);
        for_footprint_pixels(boxes, image.width, [&](std::size_t k, int, int, std::size_t i) {
            if (!image.visible[i] || image.object[i] != receiver.object) return;  // the plane's stencil
            if (!covers(f.polygons[k], normal, image.position[i])) return;
            ++fragments[i];
            result.shadowed[i] = 1;
        });
        result.raster_ms += raster.ms();
        result.cost.polygons += f.polygons.size();
        result.stencil.insert(result.stencil.end(), f.polygons.begin(), f.polygons.end());
    }
    result.cost = geometry_cost(result.cost.polygons, fragments);
    record(trace, [&](Trace& t) {
        std::size_t shadowed = 0;
        for (uint8_t s : result.shadowed) shadowed += s;
        draw_shadowed_points(
            t.add("planar.pixels", "Shadowed pixels",
                  "a pixel of a receiving plane is shadowed where a flattened caster covers it", Space::view)
                .value("image", glm::dvec2(image.width, image.height))
                .value("shadowed pixels", double(shadowed))
                .value("fill mean", result.cost.fill_mean)
                .value("fill max", result.cost.fill_max),
            result.shadowed, image, scene.camera);
    });
    result.limits = limits(r, below, beyond);
    if (const std::optional<Note> whole = alpha_tested_limit(triangles, caster_flags(scene)))
        result.limits.push_back(*whole);
    result.rule = StencilRule::cover;
    return result;
}

}  // namespace shadowlab
