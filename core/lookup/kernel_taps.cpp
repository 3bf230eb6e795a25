#include "lookup/kernel_taps.hpp"

#include <cmath>
#include <cstdint>
#include <map>
#include <mutex>
#include <numbers>

#include "math/hash.hpp"

namespace shadowlab {
namespace {

// The pixel's hash: its coordinates mixed into one word, then lowbias32.
std::uint32_t hash_pixel(std::uint32_t x, std::uint32_t y) { return lowbias32(x * 1664525u ^ y * 22695477u); }

// Mitchell's best candidate: each new point the farthest from those placed of a few uniform candidates.
std::vector<glm::dvec2> best_candidate_disk(int count) {
    std::uint32_t state = 0x9e3779b9u;
    auto uniform = [&state] {  // a linear congruential generator: fixed, portable
        state = state * 1664525u + 1013904223u;
        return double(state >> 8) / double(1u << 24);
    };
    std::vector<glm::dvec2> points;
    while (int(points.size()) < count) {
        glm::dvec2 best(0.0);
        double best_distance = -1.0;
        for (int c = 0; c < 16; ++c) {
            const double r = std::sqrt(uniform()), phi = 2.0 * std::numbers::pi * uniform();
            const glm::dvec2 candidate(r * std::cos(phi), r * std::sin(phi));
            double nearest = INFINITY;
            for (const glm::dvec2& p : points) nearest = std::min(nearest, glm::distance(p, candidate));
            if (nearest > best_distance) best = candidate, best_distance = nearest;
        }
        points.push_back(best);
    }
    return points;
}

// Tent weight along one axis at `t` in the radius's units, for taps `spacing` apart.
double tent(double t, double spacing) { return 1.0 - std::abs(t) / (1.0 + spacing); }

}  // namespace

std::vector<KernelTap> kernel_taps(PcfKernel kernel, int n) {
    std::vector<KernelTap> taps;
    if (kernel == PcfKernel::poisson) {
        for (const glm::dvec2& p : poisson_disk(n * n)) taps.push_back({p, 1.0 / double(n * n)});
        return taps;
    }
    const double spacing = n > 1 ? 2.0 / (n - 1) : 0.0;
    double total = 0.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::dvec2 offset = n > 1 ? glm::dvec2(i, j) * spacing - 1.0 : glm::dvec2(0.0);
            const double weight = kernel == PcfKernel::tent ? tent(offset.x, spacing) * tent(offset.y, spacing) : 1.0;
            taps.push_back({offset, weight});
            total += weight;
        }
    for (KernelTap& tap : taps) tap.weight /= total;
    return taps;
}

const std::vector<glm::dvec2>& poisson_disk(int count) {
    static std::mutex mutex;
    static std::map<int, std::vector<glm::dvec2>> disks;  // never erased: references stay valid
    const std::lock_guard lock(mutex);
    auto [at, inserted] = disks.try_emplace(count);
    if (inserted) at->second = best_candidate_disk(count);
    return at->second;
}

double pixel_rotation(int x, int y) {
    return 2.0 * std::numbers::pi * (double(hash_pixel(std::uint32_t(x), std::uint32_t(y))) / 4294967296.0);
}

const char* to_string(PcfKernel kernel) {
    switch (kernel) {
        case PcfKernel::box: return "box";
        case PcfKernel::tent: return "tent";
        case PcfKernel::poisson: return "poisson";
    }
    return "?";
}

}  // namespace shadowlab
