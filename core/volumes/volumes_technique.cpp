#include "volumes/volumes_technique.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "math/stopwatch.hpp"
#include "methods/step_figures.hpp"
#include "techniques/alpha_tested_limit.hpp"
#include "techniques/technique_figures.hpp"
#include "volumes/stencil_count.hpp"

namespace shadowlab {

SettingSpec volumes_count_setting() {
    return {"count", "where faces are counted: zpass (eye to visible point), zfail (visible point to infinity)",
            "zfail", 0.0,
            0.0,     {"zpass", "zfail"}};
}

namespace {

PolygonSet polygon_set(const std::vector<VolumePolygon>& polygons) {
    PolygonSet set;
    for (const VolumePolygon& p : polygons) set.add(p.vertices);
    return set;
}

std::size_t drawn_polygons(const ShadowVolume& v, CountRule rule) {
    return v.quads.size() + (rule == CountRule::zfail ? v.front_cap.size() + v.back_cap.size() : 0);
}

// Each polygon |multiplicity| times, reversed where the multiplicity is negative.
void append(std::vector<HomogeneousPolygon>& out, const std::vector<VolumePolygon>& polygons) {
    for (const VolumePolygon& p : polygons)
        for (int k = 0; k < std::abs(p.multiplicity); ++k) {
            out.push_back(p.vertices);
            if (p.multiplicity < 0) std::reverse(out.back().begin(), out.back().end());
        }
}

// What the GPU draws into the stencil buffer (Everitt and Kilgard 2002, section 3): the extruded
// silhouette quads, and for z-fail the front and back caps that close the volume.
std::vector<HomogeneousPolygon> stencil_polygons(const ShadowVolume& v, CountRule rule) {
    std::vector<HomogeneousPolygon> out;
    append(out, v.quads);
    if (rule == CountRule::zfail) {
        append(out, v.front_cap);
        append(out, v.back_cap);
    }
    return out;
}

// The open or non-manifold casters, by name; they get two-sided volumes (silhouette.hpp).
std::vector<Note> open_mesh_limits(const std::vector<ObjectTopology>& topology) {
    std::string names;
    for (const ObjectTopology& t : topology)
        if (!t.closed())
            names += (names.empty() ? "'" : ", '") + t.name + "' (" + std::to_string(t.open_edges) + " open, " +
                     std::to_string(t.non_manifold_edges) + " non-manifold edges)";
    if (names.empty()) return {};
    return {Note{NoteKind::open_mesh, names + ": two-sided volumes, silhouette edges with multiplicity"}};
}

// Pixels where the count from the eye is not 0: z-pass is wrong there (the eye is in a volume).
std::size_t eye_inside_pixels(const StencilCounts& c, const ReferenceImage& image) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < c.zpass.size(); ++i) n += image.visible[i] && c.zpass[i] != c.zfail[i];
    return n;
}

// The edges that break the casters' meshes (open or non-manifold), or every edge when none does.
SegmentSet telling_edges(const std::vector<ObjectTopology>& topology, bool all_closed) {
    SegmentSet edges;
    for (const ObjectTopology& o : topology)
        for (const MeshEdge& e : o.edges)
            if (all_closed || e.open() || e.non_manifold()) edges.segments.push_back({e.a, e.b});
    return edges;
}

// The camera's frustum with its far plane at infinity, in view space: the near rectangle and the
// four sides running to w = 0, what P_inf keeps.
PolygonSet infinite_frustum(const Camera& camera) {
    const double tan_y = std::tan(glm::radians(camera.fov_y_deg) / 2.0), tan_x = tan_y * camera.aspect;
    std::array<glm::dvec4, 4> near, far;
    const std::array<glm::dvec2, 4> signs{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
    for (int i = 0; i < 4; ++i) {
        near[i] = {signs[i].x * tan_x * camera.near, signs[i].y * tan_y * camera.near, -camera.near, 1.0};
        far[i] = {signs[i].x * tan_x, signs[i].y * tan_y, -1.0, 0.0};
    }
    PolygonSet set;
    set.add({near[0], near[1], near[2], near[3]});
    for (int i = 0; i < 4; ++i) set.add({near[i], far[i], far[(i + 1) % 4], near[(i + 1) % 4]});
    return set;
}

// A polygon set to draw, or a label saying it is empty.
Step& polygons_or_label(Step& step, const std::string& name, const std::vector<VolumePolygon>& polygons,
                        const glm::dvec3& at, Role role = Role::step) {
    if (polygons.empty()) return step.shape(name + " label", Label{at, "no " + name});
    return step.shape(name, polygon_set(polygons), role);
}

void record_geometry(Trace* trace, const std::vector<ObjectTopology>& topology, const Silhouette& s,
                     const ShadowVolume& v, const Scene& scene) {
    record(trace, [&](Trace& t) {
        int open = 0, non_manifold = 0, closed = 0;
        for (const ObjectTopology& o : topology) {
            open += o.open_edges;
            non_manifold += o.non_manifold_edges;
            closed += o.closed();
        }
        const SegmentSet edges = telling_edges(topology, open + non_manifold == 0);
        Aabb casters;
        for (const auto& [a, b] : edges.segments) casters.extend(a), casters.extend(b);
        const glm::dvec3 above =
            casters.empty() ? scene.camera.target : glm::dvec3(casters.center().x, casters.max.y, casters.center().z);
        Step& topology_step =
            t.add("volumes.topology", "Edges of the casters",
                  "each edge should join one triangle running a -> b and one running b -> a (closed, consistently "
                  "oriented)",
                  Space::world)
                .value("casting objects", double(topology.size()))
                .value("closed objects", double(closed))
                .value("open edges", double(open))
                .value("non-manifold edges", double(non_manifold))
                .shape(
                    "edges label",
                    Label{above, open + non_manifold == 0 ? "closed: " + std::to_string(closed) + " objects"
                                                          : std::to_string(open) + " open, " +
                                                                std::to_string(non_manifold) + " non-manifold edges"},
                    Role::casters);
        if (!edges.segments.empty()) topology_step.shape("edges", edges, Role::casters);
        Step& facing = t.add("volumes.light-facing", "Light-facing triangles",
                             "n . L > 0 with L the light as a homogeneous point", Space::world)
                           .value("triangles", double(s.casting.size()));
        polygons_or_label(facing, "light-facing", v.front_cap, above, Role::casters);
        draw_light(facing, scene.light, above, casters.empty() ? 1.0 : casters.diagonal());
        SegmentSet silhouette;
        double multiplicity = 0.0;
        for (const SilhouetteEdge& e : s.edges) {
            silhouette.segments.push_back({e.a, e.b});
            multiplicity += e.multiplicity;
        }
        Step& outline = t.add("volumes.silhouette", "Silhouette edges",
                              "edges between a light-facing and a back-facing triangle; multiplicity = sum of +-1 over "
                              "casting triangles",
                              Space::world)
                            .value("edges", double(s.edges.size()))
                            .value("total multiplicity", multiplicity);
        if (silhouette.segments.empty())
            outline.shape("silhouette label", Label{above, "no silhouette edge"});
        else
            outline.shape("silhouette", std::move(silhouette), Role::casters);
        Step& extrusion = t.add("volumes.extrusion", "Extruded quads",
                                "edge a -> b gives (b, a, a - L, b - L) with w = 0: to infinity", Space::world)
                              .value("quads", double(v.quads.size()));
        polygons_or_label(extrusion, "quads", v.quads, above);
        draw_light(extrusion, scene.light, above, casters.empty() ? 1.0 : casters.diagonal());
        Step& caps = t.add("volumes.caps", "Front and back caps (z-fail)",
                           "front cap: light-facing triangles; back cap: back-facing triangles projected to infinity",
                           Space::world);
        caps.value("front cap triangles", double(v.front_cap.size()))
            .value("back cap triangles", double(v.back_cap.size()));
        polygons_or_label(caps, "front cap", v.front_cap, above);
        if (v.back_cap.empty() && !s.back_cap.empty()) {
            const std::string collapsed = "directional light: the back cap collapses to one point at infinity";
            caps.value("note", collapsed);
            draw_light(caps, scene.light, above, casters.empty() ? 1.0 : casters.diagonal())
                .shape("back cap label", Label{above, collapsed}, Role::light);
        } else {
            polygons_or_label(caps, "back cap", v.back_cap, above);
        }
        const Camera& camera = scene.camera;
        t.add("volumes.projection", "Infinite far plane", "P_inf: P with far -> infinity; w = 0 points land at depth 1",
              Space::view)
            .value("view", camera.view_matrix())
            .value("projection", camera.infinite_projection_matrix())
            .shape("frustum to infinity", infinite_frustum(camera), Role::view)
            .shape("far plane label", Label{{0.0, 0.0, -camera.far}, "far plane at infinity"}, Role::view);
    });
}

void record_count(Trace* trace, const StencilCounts& c, const ReferenceImage& image, CountRule rule,
                  const GeometryResult& result, const Camera& camera) {
    record(trace, [&](Trace& t) {
        const std::size_t shadowed = std::size_t(std::count(result.shadowed.begin(), result.shadowed.end(), 1));
        const GeometryCost& cost = result.cost;
        int largest = 0;
        for (std::size_t i = 0; i < c.zpass.size(); ++i)
            largest = std::max({largest, std::abs(c.zpass[i]), std::abs(c.zfail[i])});
        Step& step =
            t.add("volumes.count", "Per-pixel count",
                  rule == CountRule::zfail
                      ? "z-fail: behind the visible point, +1 back-facing, -1 front-facing; != 0 shadowed"
                      : "z-pass: in front of the visible point, +1 front-facing, -1 back-facing; != 0 shadowed",
                  Space::view)
                .value("rule", std::string(rule == CountRule::zfail ? "zfail" : "zpass"))
                .value("image", glm::dvec2(image.width, image.height))
                .value("shadowed pixels", double(shadowed))
                .value("pixels where the eye is inside a volume", double(eye_inside_pixels(c, image)))
                .value("largest count", double(largest))
                .value("fill mean", cost.fill_mean)
                .value("fill max", cost.fill_max);
        draw_shadowed_points(step, result.shadowed, image, camera);
    });
}

// An orthographic camera has no eye to rasterize the volumes from: nothing counted, every pixel lit,
// and the limit named.
GeometryResult without_an_eye(const ReferenceImage& image) {
    GeometryResult r;
    const std::size_t pixels = image.visible.size();
    r.shadowed.assign(pixels, 0);
    r.counts = StencilCounts{std::vector<int>(pixels, 0), std::vector<int>(pixels, 0), std::vector<int>(pixels, 0)};
    r.rule = StencilRule::zfail;
    r.limits = {Note{NoteKind::no_eye_point, "orthographic camera: no shadow volume is counted"}};
    return r;
}

}  // namespace

GeometryResult compute_volumes(const Scene& scene, const WorldTriangles& triangles, const ReferenceImage& image,
                               const Settings& settings, Trace* trace) {
    // The stencil pass rasterizes the volumes from an eye point (raster/polygon_spans.hpp).
    if (scene.camera.is_orthographic()) return without_an_eye(image);
    const CountRule rule = settings.choice("count") == "zpass" ? CountRule::zpass : CountRule::zfail;
    GeometryResult r;
    const Stopwatch setup;
    const std::vector<ObjectTopology> topology = caster_topology(scene, triangles);
    const Silhouette silhouette = find_silhouette(topology, triangles, scene.light);
    const ShadowVolume volume = extrude_volume(silhouette, scene.light);
    r.setup_ms = setup.ms();
    record_geometry(trace, topology, silhouette, volume, scene);

    const Stopwatch raster;
    StencilCounts counts = count_stencil(volume, scene.camera, image, rule);
    const std::vector<int>& count = rule == CountRule::zfail ? counts.zfail : counts.zpass;
    r.shadowed.assign(count.size(), 0);
    for (std::size_t i = 0; i < count.size(); ++i) r.shadowed[i] = image.visible[i] && count[i] != 0;
    r.raster_ms = raster.ms();
    r.cost = geometry_cost(drawn_polygons(volume, rule), counts.fragments);
    record_count(trace, counts, image, rule, r, scene.camera);
    r.stencil = stencil_polygons(volume, rule);
    r.rule = rule == CountRule::zpass ? StencilRule::zpass : StencilRule::zfail;

    std::vector<Note> limits = open_mesh_limits(topology);
    if (const std::size_t wrong = eye_inside_pixels(counts, image); rule == CountRule::zpass && wrong > 0)
        limits.push_back(Note{NoteKind::eye_in_volume,
                              "z-pass counts are off at " + std::to_string(wrong) +
                                  " pixels (the eye or the near plane is in a volume); count=zfail is right"});
    if (const std::optional<Note> whole = alpha_tested_limit(triangles, caster_flags(scene))) limits.push_back(*whole);
    r.limits = std::move(limits);
    r.counts = std::move(counts);
    return r;
}

}  // namespace shadowlab
