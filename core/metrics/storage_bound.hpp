#pragma once
// The storage a view asks of a shadow map, and how much of it a method spends: Lloyd, Tuft, Yoon and
// Manocha's storage factor ("Warping and Partitioning for Low Error Shadow Maps", EGSR 2006,
// section 4; "Logarithmic Perspective Shadow Maps", ACM TOG 27(4) 2008, section 3), measured with
// ShadowLab's perspective factor of m (metrics/shadow_error.hpp) over the reference's pixels.
//
// The perspective factor at a receiver pixel i (pixel_aliasing in shadow_error.cpp): G_i takes the
// pixel's one-pixel steps right and down, slid along their view rays onto the halfway plane H_i and
// along the light onto the light's image plane (metrics/light_image.hpp), to steps there; a map is a
// function F of the place q on that plane (its (u, v) is constant along a light ray), and with N
// texels a side
//     m_perspective_i = 1 / σ_min(N DF(q_i) G_i),
// the longest extent, in pixels, of one texel carried back through G_i.
//
// needed (a method's): its texels (every map's tile, its mask's share) × (max_i m_perspective_i)².
// m_perspective scales as 1 / N (N DF above), so at N × max m every pixel's m_perspective is at
// most 1, and the texels grow with N²: those are the texels at which its worst pixel reaches 1.
// (Exact for a method whose texels all follow the texture's resolution; a method whose texel size
// is a setting, Method::finer_texels, such as virtual's pages, reaches the same count by that
// setting, to within its levels' steps.)
//
// lower_bound (the view's): m_perspective_i <= 1 asks σ_min(N DF G_i) >= 1, and of all the 2x2
// matrices with both singular values at least 1 the one of least |det| is a rotation, so
//     |det(N DF(q))| >= 1 / |det G_i| = ρ_i,
// texels per unit area of the light's image plane at q, for every receiver i whose light ray lands
// at q. |det G_i| is the area of the pixel's footprint on H_i carried to the light's image plane:
// the largest texel area allowed there. Any map (linear, warped, a paraboloid, a cube face: each
// one-to-one on the light rays it serves) spends at q at least ρ(q) = max_i ρ_i texels per unit
// area, and its texels hold the image of every q it serves, so
//     texels >= ∫ ρ(q) dq    (over the light rays of the visible receivers),
// and a setup of several maps, each serving its own receivers, at least as much (a ray served by
// two maps, cascades' at two depths, is paid twice). Hence lower_bound <= needed and
// efficiency = lower_bound / needed <= 1 for every method, up to the one-pixel finite differences
// both are measured with (exact for an orthographic map of a directional light, whose F is affine)
// and the grid's half-cell outlines (metrics/max_density_grid.hpp), which integrates ρ: each
// pixel's footprint on its surface (its two steps' images on the light's image plane, the
// parallelograms that tile the receivers' light image) asking ρ_i.
//
// With no two visible receivers on one light ray the integral is a sum over the pixels of each
// footprint's area times ρ_i: for a directional light Σ_i cos φ_light / cos φ_eye (the footprint
// on the surface meets the light at φ_light; on H_i the eye's and the light's angles are equal),
// the reciprocals of Lloyd's projection factors: one texel a pixel, less where the light sees the
// surface more obliquely than the eye does. A directional light integrates over its one plane, a
// spot or point light over the six faces of a cube about it (the omni light's whole sphere; any
// spot's cone), which give the same integral as its own image plane would.
#include "metrics/shadow_error.hpp"
#include "reference/exact_shadows.hpp"
#include "registry/method.hpp"
#include "scene/scene.hpp"

namespace shadowlab {

struct StorageFactor {
    double needed = 0.0;       // texels at which the method's max perspective m would be 1
    double lower_bound = 0.0;  // the fewest texels any single map needs for that (the view's)
    double efficiency = 0.0;   // lower_bound / needed, at most 1; 0 where nothing was measured
};

// The view's lower bounds over the reference's receiver pixels (metrics/pixel_steps.hpp) that a
// map must hold, by what its method promises to cover (Method::covers): every receiver in the
// light's reach (a spot's cone: beyond it no map stores a point) for a map of the visible (or
// seen) receivers; those the reference finds in shadow for a map of the points a caster can shadow
// (every one of which a caster's box shadows: the warps' promise holds more, so the bound holds).
struct StorageBounds {
    double every_receiver = 0.0, shadowed_receivers = 0.0;

    double for_coverage(Coverage covers) const {
        return covers == Coverage::shadowable_points ? shadowed_receivers : every_receiver;
    }
};
StorageBounds storage_lower_bounds(const Scene& scene, const ReferenceImage& reference);

// A method's storage from its texels and the perspective m it measured, against the bound for it.
StorageFactor storage_factor(double texels, const AliasingStats& m_perspective, double lower_bound);

}  // namespace shadowlab
