#pragma once
// A projection kind: how a map of that kind takes the world to (u, v, depth) and back, what the
// rasterizer clips a caster to, how the lookup's derivatives run, what the exports write and which
// GLSL the GPU pass reads. One descriptor per kind, registered once (projection_kinds.cpp); the
// lookup, the rasterizer, the exports, the views and the GPU pass read a map through its kind's
// descriptor and never ask which kind it is. The hot loops resolve it once per map (projection_kind)
// and call through its function pointers: one indirect call per vertex or point, none per texel.
#include <vector>
#include <glm/glm.hpp>

#include "maps/shadow_map.hpp"
#include "trace/trace.hpp"

namespace shadowlab {

struct ProjectionKind {
    const char* name;  // in traces, exports and JSON: "linear", "paraboloid", "cube face"

    // The mapping: world p -> (u w, v w, d_pre, w), (u, v, d) in [0,1]³ after the division where the
    // map sees p; w <= 0 where it does not (behind a perspective map's centre, a paraboloid's pole).
    glm::dvec4 (*homogeneous)(const ShadowMap& map, const glm::dvec3& world);
    // The inverse: the world point at (u, v, d).
    glm::dvec3 (*world_of)(const ShadowMap& map, const glm::dvec3& uvz);
    // The same map with its depth reversed, s = 1 − d (a reversed-Z depth format,
    // raster/depth_format.hpp), from the kind's own terms: never 1 − d after the division, which
    // cancels where d nears 1 and loses the precision reversed Z is for.
    ShadowMap (*reversed_depth)(const ShadowMap& map);

    // The rasterization clip besides w > 0 and the unit square: the signed distance to the plane a
    // caster is cut at (>= 0: drawn), interpolated along the projected edges as gl_ClipDistance does;
    // nullptr for a kind that needs none.
    double (*clip_distance)(const ShadowMap& map, const glm::dvec3& world);
    // How far the image of the straight world edge a–b bows from the straight chord a GPU draws
    // between its projected ends, in units of the map's (u, v); the rasterizer and the GPU pass split
    // the casters until it is under max_sagitta_texels (raster/paraboloid_edges.hpp). nullptr for a
    // projective kind: straight lines stay straight, world_to_uvz is the mapping, the unit cube's
    // preimage is the map's frustum (map_volume), the exports write the 4x4 and the views back-project
    // texels as flat quads and draw the camera frustum in the map.
    double (*edge_sagitta)(const ShadowMap& map, const glm::dvec3& a, const glm::dvec3& b);
    // Whether the image of the map's side fills the disc inscribed in its tile (the views draw its rim).
    bool fills_disc = false;

    // The lookup's derivatives at p (maps/map_lookup.hpp): (u, v) and the divided depth per world unit
    // along a direction, and how far back against a direction the depth falls to a value.
    glm::dvec2 (*uv_derivative)(const ShadowMap& map, const glm::dvec3& p, const glm::dvec3& direction);
    double (*depth_slope)(const ShadowMap& map, const glm::dvec3& direction, const glm::dvec3& p);
    double (*distance_back_to_depth)(const ShadowMap& map, const glm::dvec3& direction, const glm::dvec3& p,
                                     double depth);

    // What the exports and `inspect` write for a map of this kind besides its tile and bias scale,
    // under the JSON key `parameters_key` (nullptr: in the map's own object).
    std::vector<NamedValue> (*parameters)(const ShadowMap& map);
    const char* parameters_key = nullptr;
    // Whether a map of this kind is one numbered face of a set (ShadowMap::cube_face, which the cube_face
    // selection rule picks by): written as the integer "cube_face".
    bool numbered_face = false;

    // Its GLSL: viewer/render/glsl/<glsl>.glsl, defining <glsl_prefix>Homogeneous(int map, vec3 p) and
    // the other functions above under the same prefix (docs/ARCHITECTURE.md, "Adding a projection kind").
    const char* glsl;
    const char* glsl_prefix;

    bool projective() const { return edge_sagitta == nullptr; }
};

// The descriptor of a kind, the registration (projection_kinds.cpp): a kind without one does not build.
const ProjectionKind& projection_kind(Projection projection);
inline const ProjectionKind& projection_kind(const ShadowMap& map) { return projection_kind(map.projection); }

// Every registered kind, in the order of Projection.
std::vector<Projection> projection_kinds();

}  // namespace shadowlab
