#pragma once
// A shadow setup: the maps a method computed, where each lies in the texture, and how a world point
// picks its map. Every consumer (rasterizer, metrics, views, exports, the GPU pass) reads maps
// through maps/map_lookup.hpp; none assumes a single linear map.
#include <vector>
#include <glm/glm.hpp>

#include "maps/page_table.hpp"
#include "notes/note.hpp"

namespace shadowlab {

// The projection kinds, each described once by its ProjectionKind (maps/projection_kind.hpp,
// registered in maps/projection_kinds.cpp), through which every reader goes.
enum class Projection {
    linear,           // a 4x4, world (x, y, z, 1) -> (u w, v w, d_pre, w): orthographic, perspective and warped maps
    paraboloid,       // one hemisphere of a dual-paraboloid map (Brabec, Annen and Seidel 2002)
    cube_face,        // one 90° face of a cube map: a linear 4x4, numbered 0..5 for +x, -x, +y, -y, +z, -z
    log_perspective,  // a perspective 4x4 whose v is then warped logarithmically along w (LogPSM, Lloyd et al. 2008)
};
const char* to_string(Projection projection);  // its kind's name

// A paraboloid hemisphere: a world point p seen from `centre` in the hemisphere's frame, q =
// frame_from_world (p - centre), d = q / |q|, maps to (u, v) = ((d.x, d.y) / (1 + d.z) + 1) / 2 and
// depth (|q| - near) / (far - near).
struct Paraboloid {
    glm::dvec3 centre{0.0};
    glm::dmat3 frame_from_world{1.0};  // a rotation; the hemisphere is +z of the frame
    double near = 0.01, far = 1.0;
};

// A logarithmic perspective map's warp of v (Lloyd, Govindaraju, Quammen, Molnar and Manocha 2008):
// v = log(w / near) / log(far / near), w the distance its 4x4's last row gives (the perspective
// warp's distance from its centre, near at the focus region's first texel row and far at its last).
struct LogWarp {
    double near = 1.0, far = 2.0;
};

struct ShadowMap {
    Projection projection = Projection::linear;
    glm::dmat4 world_to_uvz{1.0};             // linear and cube_face: u, v, d in [0,1] after division by w
    Paraboloid paraboloid;                    // paraboloid only
    LogWarp log_warp;                         // log_perspective only: its v, u and d from world_to_uvz
    int cube_face = 0;                        // cube_face only: 0..5 for +x, -x, +y, -y, +z, -z
    glm::dvec4 viewport{0.0, 0.0, 1.0, 1.0};  // (u0, v0, u1, v1): the map's tile in the texture
    // The selection rule face_axis: the unit direction from the selection's centre this map faces.
    glm::dvec3 face_axis{0.0};
    // The map's mask (maps/map_mask.hpp): half-planes a u + b v + c >= 0, each (a, b, c), in the map's
    // (u, v); its casters are drawn only where all hold (a stencil, as a tetrahedron's faces share one
    // texture). Empty: the whole square. The lookup does not test it: a setup whose maps have masks
    // selects each point a map whose mask holds it.
    std::vector<glm::dvec3> mask;
    // Pre-division depth offset per world unit of bias along the light (XPSM step 18):
    // d' = (d_pre - z_bias_scale * bias) / w.
    double z_bias_scale = 1.0;
    // paraboloid and log_perspective: the casters' triangles are split until no projected edge bows
    // more than this many texels from its straight chord (a GPU joins projected vertices by straight
    // edges, while the true image of a straight edge is a curve); 0: drawn as given.
    double max_sagitta_texels = 0.0;
};

// How a world point picks its map among several.
struct MapSelection {
    enum class Rule {
        only,         // one map serves every point
        view_depth,   // map i serves view depths in [split_depths[i], split_depths[i + 1]) (cascades)
        tile_bounds,  // the first map whose (u, v) holds the point (seed 003's atlas lookup)
        face_axis,    // the map whose face_axis has the largest dot with p - centre (cube, tetrahedron faces)
        hemisphere,   // the paraboloid whose +z side holds p
        pages,        // the finest resident page of a virtual map's table that holds p (maps/page_table.hpp)
    };
    Rule rule = Rule::only;
    glm::dvec3 eye{0.0};  // view_depth: depth = (p - eye) . view_axis
    glm::dvec3 view_axis{0.0, 0.0, -1.0};
    std::vector<double> split_depths;  // view_depth: maps.size() + 1 increasing depths
    // view_depth: the share of each split, at its far end, over which map i crossfades into map i + 1
    // (0: a hard seam; at most 0.5).
    double blend_band = 0.0;
    glm::dvec3 centre{0.0};  // face_axis: the light's position
    PageTable pages;         // pages: the levels and which map holds each resident page
};
const char* to_string(MapSelection::Rule rule);

struct ShadowSetup {
    std::vector<ShadowMap> maps;
    MapSelection selection;
    std::vector<Note> fallbacks;  // the degradations taken, each named (notes/note.hpp)
};

}  // namespace shadowlab
