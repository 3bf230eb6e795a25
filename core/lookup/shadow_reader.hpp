#pragma once
// The one CPU lookup of shadows: a receiver point's visibility (0 shadowed .. 1 lit) read from a
// setup's depth texture with a filter and a depth bias (lookup/lookup_settings.hpp). The metrics,
// the shimmer runs and the views read shadows through it; the GPU pass
// (viewer/render/shadow_map_pass.cpp) mirrors it step by step.
#include <cmath>
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

// A value where it is finite, `otherwise` where not (a texel of no size, a light at the blocker).
inline double finite_or(double value, double otherwise) { return std::isfinite(value) ? value : otherwise; }
// A tap's offset turned by the angle whose cosine and sine are c and s.
inline glm::dvec2 rotated(const glm::dvec2& v, double c, double s) { return {c * v.x - s * v.y, s * v.x + c * v.y}; }

// The receiver under one map, biased (ShadowReader::under): what a filter's visibility reads.
struct MapReceiver {
    const ShadowMap& map;
    int index;                   // the map's in the setup
    glm::dvec3 position;         // the point looked up: the receiver, moved by the normal offset
    glm::dvec3 light_direction;  // the way light travels there
    double texels;               // across the map's tile
    glm::dvec2 uv;
    double depth;               // the point's depth, less the bias in depth units
    glm::dvec2 plane_gradient;  // receiver plane: ∂d/∂(u, v); 0 when off
    double texel_world;         // a texel's world width across the light there
};

// What a hard lookup of one map reads at a receiver: the texel nearest the biased point, the depth
// stored there and the receiver's depth compared with it (on its plane at the texel's centre when
// the receiver-plane bias is on). The receiver is shadowed by this texel when receiver > stored.
struct TexelRead {
    glm::ivec2 texel;            // in the setup's texture
    glm::dvec2 texel_centre_uv;  // in the map's (u, v)
    double stored = 1.0;         // the texel's depth
    double receiver = 0.0;       // the receiver's biased depth at that texel
};

// The texel a filter's tap reads and its centre in the reading map's (u, v).
struct TapTexel {
    glm::ivec2 texel;
    glm::dvec2 centre_uv;
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

    // The one texel a hard lookup of map `map` reads for the receiver, with the biases applied;
    // nullopt where that map does not cover the biased point (it reads lit). What the diagnosis of
    // a wrong pixel (metrics/pixel_evidence) decides from.
    std::optional<TexelRead> read_texel(int map, const Receiver& receiver) const;

    // The degradations lookups took: PCSS with a light of no size, searches clamped (from `count`,
    // summed over the lookups judged).
    std::vector<Note> fallbacks(const LookupCount& count) const;

    const ShadowSetup& setup() const { return setup_; }
    const DepthMap& depth() const { return depth_; }
    const ShadowLookup& lookup() const { return lookup_; }
    const Light& light() const { return light_; }
    const std::vector<KernelTap>& taps() const { return taps_; }  // filter_taps, read once
    // The blurred moments (vsm, evsm, msm, esm), nullopt for the other filters; and the time the blur took.
    const std::optional<MomentMap>& moments() const { return moments_; }
    double prefilter_ms() const { return prefilter_ms_; }

    // The texel a tap at (u, v) of the receiver's map reads: the nearest, kept in the map's tile,
    // except for a virtual map's page whose tap falls beyond its square onto a resident page of its
    // level (page_across): that page's texel, so that a kernel reads across page edges as across
    // one map's texels. What hard, pcf and pcss read through.
    TapTexel tap_texel(const MapReceiver& m, const glm::dvec2& uv) const;

    // The weighted share of `taps` the receiver passes, turned by `rotation` and spread over
    // radius_texels: what hard, pcf and pcss read through.
    double lit_share(const MapReceiver& m, const std::vector<KernelTap>& taps, double radius_texels, double rotation,
                     LookupCount* count) const;

private:
    std::optional<MapReceiver> under(int map, const Receiver& receiver) const;
    double map_visibility(int map, const Receiver& receiver, LookupCount* count) const;

    const ShadowSetup& setup_;
    const DepthMap& depth_;
    const Light& light_;
    ShadowLookup lookup_;
    const FilterDescriptor* filter_;  // lookup_.filter's, resolved once
    std::vector<KernelTap> taps_;     // filter_taps: hard's one texel, pcf's kernel, pcss's Poisson disk
    std::optional<MomentMap> moments_;
    double prefilter_ms_ = 0.0;
};

}  // namespace shadowlab
