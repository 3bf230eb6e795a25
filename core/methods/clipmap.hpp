#pragma once
// The clipmap of a virtual shadow map (Unreal Engine 5's directional-light virtual shadow maps):
// levels of one orthographic light view, centred on the camera, each twice the radius of the one
// before, each a virtual map of virtual_resolution² texels in pages of page_size². Page (0, 0) of
// every level's grid starts at the scene's centre in light space, and each level's window snaps to
// whole pages of its grid, so that a moving camera keeps the pages it still needs and their texels.
#include "maps/page_table.hpp"
#include "methods/light_fit.hpp"
#include "methods/shadow_inputs.hpp"

namespace shadowlab {

struct ClipmapSpec {
    int levels = 16;
    double first_level_radius = 1.0 / 64.0;  // the finest level's half-width, a share of the scene's bounding radius
    int virtual_resolution = 16384;          // texels per side of each level
    int page_size = 128;                     // texels per page side
};

struct Clipmap {
    glm::dmat4 light_from_world{1.0};  // light travels along +z; the origin is the page grids' anchor
    glm::dvec2 ls_camera{0.0};         // the camera's light-space x, y: what the levels are centred on
    double finest_texel = 0.0;         // level 0's texel width in world units
    PageTable table;                   // the levels, nothing resident yet

    int levels() const { return static_cast<int>(table.levels.size()); }
    double texel(int level) const;       // finest_texel 2^level
    double page_width(int level) const;  // texel(level) page_size
};

// The levels for this view: level l spans first_level_radius R 2^l about the camera (R the scene's
// bounding radius: the clipmap scales with the scene), depth the scene's light-space extent, the
// same for every level so that depths compare across levels.
Clipmap clipmap_around(const ShadowInputs& inputs, const ClipmapSpec& spec);

// A footprint (a pixel's width across its view ray, in world units) in levels: log2(footprint /
// finest_texel), the level whose texel it equals.
double footprint_level(const Clipmap& clipmap, double footprint);

// The level whose texel matches a footprint of `footprint_level`: the coarsest whose texel is at
// most the footprint, floor(footprint_level + bias), so that m_perspective lies in (1/2, 1] at bias
// 0 (Lloyd's m, metrics/shadow_error.hpp); a positive bias coarsens (fewer pages), a negative one
// refines. At least 0; may exceed the coarsest level.
int level_asked(double footprint_level, double bias);

}  // namespace shadowlab
