#pragma once
// The one CPU lookup of shadows: a receiver point's visibility (0 shadowed .. 1 lit) read from a
// setup's depth texture with a filter and a depth bias (lookup/lookup_settings.hpp). The metrics,
// the shimmer runs and the views read shadows through it; the GPU pass
// (viewer/render/shadow_map_pass.cpp) mirrors it step by step.
#include <cstddef>
#include <optional>
#include <vector>
#include <glm/glm.hpp>

#include "lookup/kernel_taps.hpp"
#include "lookup/lookup_settings.hpp"
#include "lookup/moment_map.hpp"
#include "maps/shadow_map.hpp"
#include "raster/depth_map.hpp"
#include "scene/light.hpp"

namespace shadowlab {

// The point being shaded.
struct Receiver {
    glm::dvec3 position;
    glm::dvec3 normal;      // unit: the side the camera sees (normal offset, receiver plane, slope-scaled bias)
    double rotation = 0.0;  // the Poisson disk's turn at this pixel (pixel_rotation)
};

// What lookups cost and where they degraded: summed over the calls given the same counter.
struct LookupCount {
    std::size_t lookups = 0;           // map lookups (two inside a cascades' blend band)
    std::size_t taps = 0;              // texel reads (a bilinear moment read: 4)
    std::size_t searches_clamped = 0;  // pcss: blocker searches cut at kMaxSearchTexels
};

class ShadowReader {
public:
    // PCSS's blocker search reaches at most this many texels of the map from the point: the light's
    // footprint grows with the distance to the map's near plane, and a search beyond this costs more
    // than any penumbra is worth (a named fallback, counted in LookupCount).
    static constexpr double kMaxSearchTexels = 32.0;

    // Reads `depth` (the setup's maps rasterized) as `lookup` says; blurs the moments once when the
    // filter reads them. Keeps references to setup, depth and light: use it while they live.
    ShadowReader(const ShadowSetup& setup, const DepthMap& depth, const Light& light, const ShadowLookup& lookup);

    // The share of the light the receiver sees under the map the setup selects; inside a blend band
    // the two maps' shares crossfaded; no map, or off its square: 1 (lit).
    double visibility(const Receiver& receiver, LookupCount* count = nullptr) const;

    // The degradations lookups took: PCSS with a light of no size, searches clamped (from `count`,
    // summed over the lookups judged).
    std::vector<Note> fallbacks(const LookupCount& count) const;

    const ShadowSetup& setup() const { return setup_; }
    const DepthMap& depth() const { return depth_; }
    const ShadowLookup& lookup() const { return lookup_; }
    // The blurred moments (vsm, evsm), nullopt for the other filters; and the time the blur took.
    const std::optional<MomentMap>& moments() const { return moments_; }
    double prefilter_ms() const { return prefilter_ms_; }

private:
    struct MapReceiver;  // the receiver under one map: its (u, v), biased depth, texel size
    std::optional<MapReceiver> under(int map, const Receiver& receiver) const;
    double map_visibility(int map, const Receiver& receiver, LookupCount* count) const;
    double lit_share(const MapReceiver& m, const std::vector<KernelTap>& taps, double radius_texels, double rotation,
                     LookupCount* count) const;
    double soft_shadow(const MapReceiver& m, const Receiver& receiver, LookupCount* count) const;
    double chebyshev_visibility(const MapReceiver& m, LookupCount* count) const;

    const ShadowSetup& setup_;
    const DepthMap& depth_;
    const Light& light_;
    ShadowLookup lookup_;
    std::vector<KernelTap> taps_;  // filter_taps: hard's one texel, pcf's kernel, pcss's Poisson disk
    std::optional<MomentMap> moments_;
    double prefilter_ms_ = 0.0;
};

}  // namespace shadowlab
