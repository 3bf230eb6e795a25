#pragma once
// The flatland cross-section of a shadow setup (Lloyd et al. 2008 draw their analysis there): in
// the plane of the view and the light (flatland/flatland_plane.hpp), the camera's frustum, the
// intersection body B, each map's volume (for a warp, the warp frustum: the volume its perspective
// maps onto the unit cube) and the map's texel boundaries u = i/R and v = j/R, every k-th, traced
// in the plane as world polylines, for any projection kind (through its descriptor's mapping: a
// kind that bends straight lines gives curves). Core computes it; the Flatland view draws it.
#include <vector>
#include <glm/glm.hpp>

#include "flatland/flatland_plane.hpp"
#include "flatland/level_curves.hpp"
#include "flatland/texel_density.hpp"
#include "maps/shadow_map.hpp"
#include "methods/shadow_inputs.hpp"
#include "scene/tessellation.hpp"

namespace shadowlab {

// One texel boundary of one map in the plane: where the map's u (axis 0) or v (axis 1) is index / R.
struct TexelLine {
    int map = 0;
    int axis = 0;
    int index = 0;  // the boundary's number, 0..R: a multiple of the stride
    Polyline points;
};

// A map's volume cut by the plane: a convex polygon for a projective kind (its unit cube's preimage,
// maps/map_lookup.hpp map_volume), else its boundary's level curves (where one of u, v, d leaves [0, 1]).
struct MapSection {
    int map = 0;
    int texels = 0;                 // R: texels per side of its tile
    std::vector<Polyline> outline;  // closed polylines (first point repeated last) or open pieces
};

// A polygon as a closed polyline: its first corner repeated last (none for an empty polygon).
Polyline closed_outline(std::vector<glm::dvec3> polygon);

struct Flatland {
    FlatlandPlane plane;
    std::vector<Note> fallbacks;                // light_along_view when the plane fell back
    glm::dvec2 frame_min{0.0}, frame_max{0.0};  // the (s, t) rectangle shown: B's section and the eye, with a margin
    std::vector<glm::dvec3> frustum;            // the camera frustum's section, counter-clockwise about the normal
    std::vector<glm::dvec3> body;               // B's section (empty: the plane misses B)
    std::vector<MapSection> map_volumes;        // one per map the frame shows
    int texels = 0;                             // R: texels per side of the widest tile
    int stride = 1;                             // k: every k-th boundary is traced, a power of two
    std::vector<TexelLine> texel_lines;         // within the frame, each where its map serves (the selection) and
                                                // holds the point in its unit cube
    std::optional<DepthSpan> view_axis;         // where the view axis runs through the scene (view_axis_span)
};

// At most this many texel boundaries (of u and of v together) across the frame's longer side where
// they are densest: about 8 pixels apart in a 1000-pixel view, so that lines stay apart.
constexpr double kMostLinesAcross = 128.0;

// The flatland of a setup drawn into a texture of `texture_resolution` texels per side.
Flatland flatland(const ShadowInputs& inputs, const ShadowSetup& setup, int texture_resolution);

// How many of the traced texel boundaries cross the view axis (t = 0) at view depths in [from, to).
int view_axis_crossings(const Flatland& flatland, double from, double to);

// Boundaries crossed per unit of view depth over the first and the last fifth of the view axis's
// span: how far apart the map's texels fall along the view near the eye and far from it.
struct AxisLineDensity {
    DepthSpan near, far;                       // the two stretches of the view axis
    double near_lines = 0.0, far_lines = 0.0;  // boundaries per unit of view depth in each
};
std::optional<AxisLineDensity> axis_line_density(const Flatland& flatland);

// The scene's surfaces cut by the plane: one segment per triangle the plane crosses (the ground's
// line, each object's outline), for the picture's bearings.
std::vector<std::pair<glm::dvec3, glm::dvec3>> scene_section(const WorldTriangles& triangles,
                                                             const FlatlandPlane& plane);

}  // namespace shadowlab
