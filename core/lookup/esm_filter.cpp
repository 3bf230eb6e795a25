// Exponential shadow maps (lookup/exponential_shadow.hpp): one blurred moment, e^{c z}.
#include <cmath>
#include <limits>
#include <string>

#include "lookup/exponential_shadow.hpp"
#include "lookup/lookup_settings.hpp"
#include "lookup/moment_read.hpp"
#include "lookup/shipped_filters.hpp"

namespace shadowlab {
namespace {

glm::dvec4 exponential_moment(double depth, const ShadowFilter& filter) {
    return {std::exp(filter.esm_exponent * depth), 0.0, 0.0, 0.0};
}
// The mean carried back to depth, ln(E[e^{cz}]) / c (between the mean and the farthest depth); no
// deviation: one moment holds none.
glm::dvec2 exponential_mean(const glm::dvec4& stored, const ShadowFilter& filter) {
    return {std::log(stored.x) / filter.esm_exponent, std::numeric_limits<double>::quiet_NaN()};
}

double exponential_visibility(const ShadowReader& reader, const MapReceiver& m, const Receiver&, LookupCount* count) {
    return esm_visibility(moments_at(reader, m, count).x, m.depth, reader.lookup().filter.esm_exponent);
}

SettingSpec exponent_setting() {
    char limit[16];
    std::snprintf(limit, sizeof limit, "%.2f", esm_exponent_limit());
    return {.name = "esm_exponent",
            .description =
                std::string("esm: c of e^(c d); at most ln(FLT_MAX) = ") + limit + ", where e^c overflows a float32",
            .default_value = "80",
            .min = 0.01,
            .max = esm_exponent_limit()};
}

}  // namespace

FilterDescriptor esm_filter() {
    return {.name = "esm",
            .description = "exponential shadow map: the blurred e^{c z} times e^{−c d}, clamped to 1",
            .settings = {kernel_size_setting(), exponent_setting()},
            .taps = no_taps,
            .texel_reads = bilinear_reads,
            .moments = {.of_depth = exponential_moment,
                        .depth_statistics = exponential_mean,
                        .mean_words = "the mean m₁ of e^(c z), as a depth ln(m₁)/c"},
            .visibility = exponential_visibility};
}

}  // namespace shadowlab
