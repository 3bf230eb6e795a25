#pragma once
// Where a filter's taps fall around the lookup, in units of its radius, and their weights: a box or
// tent grid, or a Poisson disk turned per pixel. The GPU pass reads the same lists.
#include <vector>
#include <glm/glm.hpp>

namespace shadowlab {

enum class PcfKernel {
    box,      // N×N taps, equal weights
    tent,     // N×N taps, weights falling linearly to zero one tap spacing past the radius
    poisson,  // N² taps of a Poisson disk, turned per pixel (the banding of a regular grid becomes noise)
};
const char* to_string(PcfKernel kernel);

struct KernelTap {
    glm::dvec2 offset;  // in the kernel's radius: within [-1, 1]² (box, tent) or the unit disc (poisson)
    double weight;      // the taps' weights sum to 1
};

// box and tent: an n×n grid spanning [-1, 1]² (one tap at the centre for n = 1); tent weights fall
// linearly along each axis to zero one tap spacing beyond the radius. poisson: poisson_disk(n²),
// equal weights.
std::vector<KernelTap> kernel_taps(PcfKernel kernel, int n);

// `count` points in the unit disc, no two closer than the distribution allows (Mitchell's best
// candidate, 16 candidates per point, from a fixed seed: every run and the GPU get the same disk).
const std::vector<glm::dvec2>& poisson_disk(int count);

// The Poisson disk's turn at image pixel (x, y) (row 0 at the top), in radians [0, 2π): an integer
// hash of the pixel, which the GPU pass computes alike from gl_FragCoord.
double pixel_rotation(int x, int y);

}  // namespace shadowlab
