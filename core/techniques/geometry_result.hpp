#pragma once
// What a geometric technique (shadow volumes, planar projection) computes, all of it: its verdict
// per camera pixel, the polygons a GPU draws into the stencil buffer and how they count, the CPU's
// counts, what drawing them costs and the limits it met. The viewer draws these; it rebuilds none.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/homogeneous_clip.hpp"
#include "notes/note.hpp"

namespace shadowlab {

// What drawing the technique's geometry costs on a GPU: how many polygons, and how many fragments
// of them land on each camera pixel (over the whole image: mean and max).
struct GeometryCost {
    std::size_t polygons = 0;
    double fill_mean = 0.0, fill_max = 0.0;
};

// The cost of `polygons` polygons that drew `fragments[i]` fragments on pixel i.
GeometryCost geometry_cost(std::size_t polygons, const std::vector<int>& fragments);

// How the stencil polygons mark the shadowed pixels.
enum class StencilRule {
    zpass,  // volume faces in front of the visible point: front +1, back -1 (Heidmann)
    zfail,  // volume faces behind it: back +1, front -1 (Everitt and Kilgard 2002, Carmack's reverse)
    cover   // flattened casters on the receiving plane: 1 where drawn (Blinn, planar projection)
};

// A shadow volume's stencil pass on the CPU, both counts per pixel (volumes/stencil_count.hpp counts them).
struct StencilCounts {
    // Per pixel, row-major like the image. Where nothing is visible the counts are 0.
    std::vector<int> zpass;      // front-facing faces in front of the visible point, minus back-facing ones
    std::vector<int> zfail;      // back-facing faces behind it (to infinity), minus front-facing ones
    std::vector<int> fragments;  // faces the rule draws that the near plane leaves: quads, and caps for z-fail
};

struct GeometryResult {
    std::vector<uint8_t> shadowed;  // per pixel of the image: 1 where the visible point is in shadow
    GeometryCost cost;
    std::vector<Note> limits;  // each named (notes/note.hpp)
    double setup_ms = 0.0;     // building the geometry
    double raster_ms = 0.0;    // judging the pixels (the stencil or projection pass)
    // The polygons, each as often as its multiplicity, counter-clockwise seen from outside; w = 0 at infinity.
    std::vector<HomogeneousPolygon> stencil;
    StencilRule rule = StencilRule::cover;
    std::optional<StencilCounts> counts;  // shadow volumes: the CPU's count per pixel of the image
};

}  // namespace shadowlab
