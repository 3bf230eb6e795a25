#include "volumes/volumes_technique.hpp"

#include <algorithm>
#include <cstdlib>

#include "math/stopwatch.hpp"
#include "volumes/stencil_count.hpp"

namespace shadowlab {

SettingSpec volumes_count_setting() {
    return {"count", "where faces are counted: zpass (eye to visible point), zfail (visible point to infinity)", "zfail",
            0.0, 0.0, {"zpass", "zfail"}};
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

void record_geometry(Trace* trace, const std::vector<ObjectTopology>& topology, const Silhouette& s,
                     const ShadowVolume& v, const Camera& camera) {
    record(trace, [&](Trace& t) {
        int open = 0, non_manifold = 0, closed = 0;
        for (const ObjectTopology& o : topology) {
            open += o.open_edges;
            non_manifold += o.non_manifold_edges;
            closed += o.closed();
        }
        t.add("volumes.topology", "Edges of the casters",
              "each edge should join one triangle running a -> b and one running b -> a (closed, consistently oriented)",
              Space::world)
            .value("casting objects", double(topology.size())).value("closed objects", double(closed))
            .value("open edges", double(open)).value("non-manifold edges", double(non_manifold));
        t.add("volumes.light-facing", "Light-facing triangles", "n . L > 0 with L the light as a homogeneous point",
              Space::world)
            .value("triangles", double(s.casting.size()))
            .shape("light-facing", polygon_set(v.front_cap));
        SegmentSet edges;
        double multiplicity = 0.0;
        for (const SilhouetteEdge& e : s.edges) {
            edges.segments.push_back({e.a, e.b});
            multiplicity += e.multiplicity;
        }
        t.add("volumes.silhouette", "Silhouette edges",
              "edges between a light-facing and a back-facing triangle; multiplicity = sum of +-1 over casting triangles",
              Space::world)
            .value("edges", double(s.edges.size())).value("total multiplicity", multiplicity)
            .shape("silhouette", std::move(edges));
        t.add("volumes.extrusion", "Extruded quads", "edge a -> b gives (b, a, a - L, b - L) with w = 0: to infinity",
              Space::world)
            .value("quads", double(v.quads.size()))
            .shape("quads", polygon_set(v.quads));
        Step& caps = t.add("volumes.caps", "Front and back caps (z-fail)",
                           "front cap: light-facing triangles; back cap: back-facing triangles projected to infinity",
                           Space::world);
        caps.value("front cap triangles", double(v.front_cap.size()))
            .value("back cap triangles", double(v.back_cap.size()))
            .shape("front cap", polygon_set(v.front_cap)).shape("back cap", polygon_set(v.back_cap));
        if (v.back_cap.empty() && !s.back_cap.empty())
            caps.value("note", std::string("directional light: the back cap collapses to one point at infinity"));
        t.add("volumes.projection", "Infinite far plane", "P_inf: P with far -> infinity; w = 0 points land at depth 1",
              Space::view)
            .value("view", camera.view_matrix()).value("projection", camera.infinite_projection_matrix());
    });
}

void record_count(Trace* trace, const StencilCounts& c, const ReferenceImage& image, CountRule rule,
                  const GeometryCost& cost, std::size_t shadowed) {
    record(trace, [&](Trace& t) {
        int largest = 0;
        for (std::size_t i = 0; i < c.zpass.size(); ++i)
            largest = std::max({largest, std::abs(c.zpass[i]), std::abs(c.zfail[i])});
        t.add("volumes.count", "Per-pixel count",
              rule == CountRule::zfail ? "z-fail: behind the visible point, +1 back-facing, -1 front-facing; != 0 shadowed"
                                       : "z-pass: in front of the visible point, +1 front-facing, -1 back-facing; != 0 shadowed",
              Space::view)
            .value("rule", std::string(rule == CountRule::zfail ? "zfail" : "zpass"))
            .value("image", glm::dvec2(image.width, image.height))
            .value("shadowed pixels", double(shadowed))
            .value("pixels where the eye is inside a volume", double(eye_inside_pixels(c, image)))
            .value("largest count", double(largest))
            .value("fill mean", cost.fill_mean).value("fill max", cost.fill_max);
    });
}

}  // namespace

GeometryResult compute_volumes(const Scene& scene, const WorldTriangles& triangles, const ReferenceImage& image,
                                const Settings& settings, Trace* trace) {
    const CountRule rule = settings.choice("count") == "zpass" ? CountRule::zpass : CountRule::zfail;
    GeometryResult r;
    const Stopwatch setup;
    const std::vector<ObjectTopology> topology = caster_topology(scene, triangles);
    const Silhouette silhouette = find_silhouette(topology, triangles, scene.light);
    const ShadowVolume volume = extrude_volume(silhouette, scene.light);
    r.setup_ms = setup.ms();
    record_geometry(trace, topology, silhouette, volume, scene.camera);

    const Stopwatch raster;
    StencilCounts counts = count_stencil(volume, scene.camera, image, rule);
    const std::vector<int>& count = rule == CountRule::zfail ? counts.zfail : counts.zpass;
    r.shadowed.assign(count.size(), 0);
    std::size_t shadowed = 0;
    for (std::size_t i = 0; i < count.size(); ++i) shadowed += r.shadowed[i] = image.visible[i] && count[i] != 0;
    r.raster_ms = raster.ms();
    r.cost = geometry_cost(drawn_polygons(volume, rule), counts.fragments);
    record_count(trace, counts, image, rule, r.cost, shadowed);
    r.stencil = stencil_polygons(volume, rule);
    r.rule = rule == CountRule::zpass ? StencilRule::zpass : StencilRule::zfail;

    std::vector<Note> limits = open_mesh_limits(topology);
    if (const std::size_t wrong = eye_inside_pixels(counts, image); rule == CountRule::zpass && wrong > 0)
        limits.push_back(Note{NoteKind::eye_in_volume,
                                         "z-pass counts are off at " + std::to_string(wrong) +
                                             " pixels (the eye or the near plane is in a volume); count=zfail is right"});
    r.limits = std::move(limits);
    r.counts = std::move(counts);
    return r;
}

}  // namespace shadowlab
