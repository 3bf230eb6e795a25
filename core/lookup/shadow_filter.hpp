#pragma once
// How a lookup turns a map's texels into a visibility in [0, 1]: the filters every engine ships,
// each a setting of every map method (lookup/lookup_settings.hpp), read alike by the CPU lookup
// (lookup/shadow_lookup.hpp) and the GPU pass (viewer/render/shadow_map_pass.cpp).
namespace shadowlab {

enum class FilterKind {
    hard,  // the nearest texel against the receiver's depth: 0 or 1
    pcf,   // percentage-closer filtering (Reeves, Salesin and Cook 1987): the weighted share of taps that pass
    vsm,   // variance shadow map: Chebyshev's bound on the blurred moments (d, d²)
    evsm,  // exponential VSM: the same on the moments of e^{c⁺d} and −e^{−c⁻d}, the tighter bound of the two
    pcss,  // percentage-closer soft shadows (Fernando 2005): blocker search, penumbra width, PCF of that width
};
enum class PcfKernel {
    box,      // N×N taps, equal weights
    tent,     // N×N taps, weights falling linearly to zero one tap spacing past the radius
    poisson,  // N² taps of a Poisson disk, turned per pixel (the banding of a regular grid becomes noise)
};

struct ShadowFilter {
    FilterKind kind = FilterKind::hard;
    PcfKernel kernel = PcfKernel::box;  // pcf; pcss always takes the Poisson disk
    int kernel_size = 3;                // N: N×N taps (box, tent) or N² (poisson); pcss: N² per pass;
                                        // vsm, evsm: the blur's side in texels
    double radius_texels = 1.0;         // pcf: the kernel's half-width in the map's texels
    double radius_world = 0.0;          // pcf: the half-width in world units across the light (> 0 overrides texels)
    double min_variance = 1e-6;         // vsm, evsm: the variance's floor, in squared depth units
    double bleed_reduction = 0.0;       // vsm, evsm: linstep's cut (chebyshev.hpp)
    double evsm_positive = 40.0, evsm_negative = 5.0;  // evsm: the exponents c⁺, c⁻ (<= evsm_exponent_limit())

    bool reads_moments() const { return kind == FilterKind::vsm || kind == FilterKind::evsm; }
    // Texel reads of one map lookup: 1 (hard), N² (pcf), 2 N² (pcss: search and filter), 4 (a
    // bilinear read of the prefiltered moments).
    int taps() const;
};

const char* to_string(FilterKind kind);
const char* to_string(PcfKernel kernel);

}  // namespace shadowlab
