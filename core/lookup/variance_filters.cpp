// Variance shadow maps (Donnelly and Lauritzen 2006) and exponential variance shadow maps
// (Lauritzen and McCool 2008): Chebyshev's bound (lookup/chebyshev.hpp) on the prefiltered moments
// (lookup/moment_map.hpp) at the receiver's depth.
#include "lookup/chebyshev.hpp"
#include "lookup/lookup_settings.hpp"
#include "lookup/shadow_reader.hpp"
#include "lookup/shipped_filters.hpp"

namespace shadowlab {
namespace {

std::vector<KernelTap> no_taps(const ShadowFilter&) { return {}; }
int bilinear_reads(const ShadowFilter&) { return 4; }

glm::dvec4 moments_at(const ShadowReader& reader, const MapReceiver& m, LookupCount* count) {
    if (count) count->taps += 4;
    return sample_moments(*reader.moments(), m.map, m.uv);
}

double variance_bound(const ShadowReader& reader, const MapReceiver& m, const Receiver&, LookupCount* count) {
    const ShadowFilter& f = reader.lookup().filter;
    const glm::dvec4 mo = moments_at(reader, m, count);
    const double p = chebyshev_upper_bound(mo.x, std::max(mo.y - mo.x * mo.x, f.min_variance), m.depth);
    return reduce_light_bleeding(p, f.bleed_reduction);
}

// EVSM's floor on the variance scales with the warp's slope, (c e^{cd})², so that it is the same in
// depth units; the tighter of the two warps' bounds.
double exponential_variance_bound(const ShadowReader& reader, const MapReceiver& m, const Receiver&,
                                  LookupCount* count) {
    const ShadowFilter& f = reader.lookup().filter;
    const glm::dvec4 mo = moments_at(reader, m, count);
    const double positive = evsm_positive_warp(m.depth, f.evsm_positive);
    const double negative = evsm_negative_warp(m.depth, f.evsm_negative);
    const double floor_positive = f.min_variance * std::pow(f.evsm_positive * positive, 2);
    const double floor_negative = f.min_variance * std::pow(f.evsm_negative * negative, 2);
    const double p = std::min(chebyshev_upper_bound(mo.x, std::max(mo.y - mo.x * mo.x, floor_positive), positive),
                              chebyshev_upper_bound(mo.z, std::max(mo.w - mo.z * mo.z, floor_negative), negative));
    return reduce_light_bleeding(p, f.bleed_reduction);
}

std::vector<SettingSpec> variance_settings() {
    return {kernel_size_setting(),
            {.name = "min_variance",
             .description = "vsm, evsm: the floor of the moments' variance (squared depth units)",
             .default_value = "1e-6",
             .min = 0,
             .max = 0.01},
            {.name = "bleed_reduction",
             .description = "vsm, evsm: light bleeding reduction, Chebyshev's bound below this cut to 0 (linstep)",
             .default_value = "0",
             .min = 0,
             .max = 0.99}};
}

}  // namespace

FilterDescriptor vsm_filter() {
    return {.name = "vsm",
            .description = "variance shadow map: Chebyshev's bound on the blurred moments (d, d²)",
            .settings = variance_settings(),
            .taps = no_taps,
            .texel_reads = bilinear_reads,
            .moments = Moments::depth,
            .visibility = variance_bound};
}

FilterDescriptor evsm_filter() {
    std::vector<SettingSpec> settings = variance_settings();
    const double limit = evsm_exponent_limit();
    settings.push_back(
        {.name = "evsm_positive",
         .description = "evsm: c+ of e^(c+ d); at most ln(FLT_MAX)/2 = 44.36, where e^(2c) overflows a float32",
         .default_value = "40",
         .min = 0.01,
         .max = limit});
    settings.push_back({.name = "evsm_negative",
                        .description = "evsm: c- of -e^(-c- d); at most ln(FLT_MAX)/2 = 44.36",
                        .default_value = "5",
                        .min = 0.01,
                        .max = limit});
    return {.name = "evsm",
            .description = "exponential VSM: Chebyshev's bound on the moments of e^{c⁺d} and −e^{−c⁻d}, the tighter",
            .settings = std::move(settings),
            .taps = no_taps,
            .texel_reads = bilinear_reads,
            .moments = Moments::exponential,
            .visibility = exponential_variance_bound};
}

}  // namespace shadowlab
