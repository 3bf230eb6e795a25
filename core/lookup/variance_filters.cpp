// Variance shadow maps (Donnelly and Lauritzen 2006) and exponential variance shadow maps
// (Lauritzen and McCool 2008): Chebyshev's bound (lookup/chebyshev.hpp) on the prefiltered moments
// (lookup/moment_map.hpp) at the receiver's depth.
#include "lookup/chebyshev.hpp"
#include "lookup/lookup_settings.hpp"
#include "lookup/moment_read.hpp"
#include "lookup/shipped_filters.hpp"

namespace shadowlab {
namespace {

// VSM's moments: the depth and its square.
glm::dvec4 depth_moments(double depth, const ShadowFilter&) { return {depth, depth * depth, 0.0, 0.0}; }
glm::dvec2 depth_statistics(const glm::dvec4& m, const ShadowFilter&) { return mean_and_deviation(m.x, m.y); }

// EVSM's: each warp and its square.
glm::dvec4 exponential_moments(double depth, const ShadowFilter& filter) {
    const double positive = evsm_positive_warp(depth, filter.evsm_positive);
    const double negative = evsm_negative_warp(depth, filter.evsm_negative);
    return {positive, positive * positive, negative, negative * negative};
}
// The positive warp's mean μ = E[e^{c⁺d}] carried back to depth, ln(μ) / c⁺, and its deviation to
// first order, σ / (c⁺ μ) (d(e^{c⁺d}) = c⁺ e^{c⁺d} dd).
glm::dvec2 exponential_statistics(const glm::dvec4& m, const ShadowFilter& filter) {
    const double sigma = mean_and_deviation(m.x, m.y).y;
    return {std::log(m.x) / filter.evsm_positive, sigma / (filter.evsm_positive * m.x)};
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
            bleed_reduction_setting()};
}

}  // namespace

FilterDescriptor vsm_filter() {
    return {.name = "vsm",
            .description = "variance shadow map: Chebyshev's bound on the blurred moments (d, d²)",
            .settings = variance_settings(),
            .taps = no_taps,
            .texel_reads = bilinear_reads,
            .moments = {.of_depth = depth_moments,
                        .depth_statistics = depth_statistics,
                        .mean_words = "the mean m₁ of the depth",
                        .deviation_words = "√(m₂ − m₁²)"},
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
            .moments = {.of_depth = exponential_moments,
                        .depth_statistics = exponential_statistics,
                        .mean_words = "the mean m₁ of e^(c⁺d), as a depth ln(m₁)/c⁺",
                        .deviation_words = "σ/(c⁺ m₁)"},
            .visibility = exponential_variance_bound};
}

}  // namespace shadowlab
