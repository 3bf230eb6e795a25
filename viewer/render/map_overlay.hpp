#pragma once
// What the Camera view can paint over the shading of a map method, per fragment (seed 003's
// "shadows per split" and "resolution per split"): the map the setup's rule gives the fragment, or
// how many of that map's texels fall on its pixel.
#include <algorithm>
#include <array>
#include <cmath>
#include <glm/glm.hpp>

namespace shadowlab {

enum class MapOverlay {
    none,
    cascade_index,     // the selected map's colour from kMapPalette (inside a blend band: both, crossfaded)
    texels_per_pixel,  // the map's texel footprint against the pixel, on a log ramp
};

// One distinct colour per map of a setup (Okabe and Ito's colour-blind-safe set, and a brown):
// map i is kMapPalette[i] in the overlay and its legend.
inline constexpr std::array<glm::vec3, 8> kMapPalette{{
    {0.90f, 0.62f, 0.00f},  // orange
    {0.34f, 0.71f, 0.91f},  // sky blue
    {0.00f, 0.62f, 0.45f},  // bluish green
    {0.94f, 0.89f, 0.26f},  // yellow
    {0.00f, 0.45f, 0.70f},  // blue
    {0.84f, 0.37f, 0.00f},  // vermilion
    {0.80f, 0.47f, 0.65f},  // reddish purple
    {0.55f, 0.34f, 0.29f},  // brown
}};

// The overlay's share of a fragment's colour: enough to read the colour, little enough that the
// shading and the shadows still show through.
inline constexpr float kOverlayStrength = 0.6f;

// Texels per pixel from 2^-kTexelsLog2Range to 2^kTexelsLog2Range, as the Error view's 1/8..8. The
// ramp runs the Error view's way, so that a colour means the same in both: its dark end many texels
// per pixel (over-sampled), its bright end few (a texel wider than the pixel: under-sampled).
inline constexpr double kTexelsLog2Range = 3.0;
inline double texels_ramp_position(double texels_per_pixel) {
    return (kTexelsLog2Range - std::log2(std::max(texels_per_pixel, 1e-6))) / (2.0 * kTexelsLog2Range);
}

}  // namespace shadowlab
