#include "model/technique_inspection.hpp"

#include <algorithm>
#include <cstdlib>

#include "planar/planar_projection.hpp"
#include "volumes/shadow_volume.hpp"

namespace shadowlab {
namespace {

// Each polygon |multiplicity| times, reversed where the multiplicity is negative.
void append(std::vector<HomogeneousPolygon>& out, const std::vector<VolumePolygon>& polygons) {
    for (const VolumePolygon& p : polygons)
        for (int k = 0; k < std::abs(p.multiplicity); ++k) {
            out.push_back(p.vertices);
            if (p.multiplicity < 0) std::reverse(out.back().begin(), out.back().end());
        }
}

// The volume the GPU draws (Everitt and Kilgard 2002, section 3): the extruded silhouette quads,
// and for z-fail the front and back caps that close it.
void add_volume(TechniqueInspection& out, const Scene& scene, const WorldTriangles& triangles, const Settings& settings) {
    const CountRule rule = settings.choice("count") == "zpass" ? CountRule::zpass : CountRule::zfail;
    const ShadowVolume volume = extrude_volume(find_silhouette(caster_topology(scene, triangles), triangles, scene.light),
                                               scene.light);
    out.rule = rule == CountRule::zpass ? StencilRule::zpass : StencilRule::zfail;
    append(out.stencil, volume.quads);
    if (rule == CountRule::zfail) {
        append(out.stencil, volume.front_cap);
        append(out.stencil, volume.back_cap);
    }
    out.counts = count_stencil(volume, scene.camera, out.image, rule);
}

// Blinn's flattened casters on every receiving plane.
void add_flattened(TechniqueInspection& out, const Scene& scene, const WorldTriangles& triangles) {
    out.rule = StencilRule::cover;
    for (int o = 0; o < int(scene.objects.size()); ++o) {
        if (!scene.objects[o].receives || scene.objects[o].shape != Shape::plane) continue;
        if (const std::optional<ReceiverPlane> plane = receiver_plane(scene, o)) {
            const FlattenedCasters f = flatten_casters(scene, triangles, *plane);
            out.stencil.insert(out.stencil.end(), f.polygons.begin(), f.polygons.end());
        }
    }
}

}  // namespace

TechniqueInspection inspect_technique(const Technique& technique, const Scene& scene, const WorldTriangles& triangles,
                                      const Settings& settings, int width, int height, Trace* trace) {
    TechniqueInspection out;
    out.technique = &technique;
    out.image = exact_reference(scene, triangles, width, height);
    out.result = technique.compute(scene, triangles, out.image, settings, trace);
    if (technique.name == "volumes")
        add_volume(out, scene, triangles, settings);
    else
        add_flattened(out, scene, triangles);
    return out;
}

}  // namespace shadowlab
