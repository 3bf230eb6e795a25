// Moment shadow maps (Peters and Klein 2015): the Hamburger 4MSM bound (lookup/moment_shadow.hpp)
// on the blurred moments (d, d², d³, d⁴), in float32 or, as engines ship it (MJP's Shadows sample),
// 16 bits a moment in the paper's optimized basis: 64 bits a texel, VSM's cost in memory.
#include "lookup/chebyshev.hpp"
#include "lookup/lookup_settings.hpp"
#include "lookup/moment_read.hpp"
#include "lookup/moment_shadow.hpp"
#include "lookup/shipped_filters.hpp"

namespace shadowlab {
namespace {

// The moments a texel blurs: the powers themselves, or in the quantized basis (affine: the blur of
// the optimized moments is the optimized blur).
glm::dvec4 texel_moments(double depth, const ShadowFilter& filter) {
    const glm::dvec4 power = power_moments(depth);
    return filter.msm_quantized ? optimized_moments(power) : power;
}
glm::dvec4 stored_moments(const glm::dvec4& blurred, const ShadowFilter& filter) {
    return filter.msm_quantized ? rounded_to_unorm16(blurred) : blurred;
}
glm::dvec4 power_of_stored(const glm::dvec4& stored, const ShadowFilter& filter) {
    return filter.msm_quantized ? power_from_optimized(stored) : stored;
}
glm::dvec2 moment_statistics(const glm::dvec4& stored, const ShadowFilter& filter) {
    const glm::dvec4 b = power_of_stored(stored, filter);
    return mean_and_deviation(b.x, b.y);
}

double hamburger_visibility(const ShadowReader& reader, const MapReceiver& m, const Receiver&, LookupCount* count) {
    const ShadowFilter& f = reader.lookup().filter;
    const glm::dvec4 b = power_of_stored(moments_at(reader, m, count), f);
    return reduce_light_bleeding(1.0 - hamburger_shadow_intensity(b, m.depth, f.msm_moment_bias), f.bleed_reduction);
}

}  // namespace

FilterDescriptor msm_filter() {
    return {.name = "msm",
            .description =
                "moment shadow map: the sharpest lower bound on the shadow from four blurred moments "
                "(Hamburger 4MSM)",
            .settings = {kernel_size_setting(),
                         {.name = "msm_moment_bias",
                          .description = "msm: α, the moments pulled toward (½, ½, ½, ½) against rounding (Peters "
                                         "and Klein: 3e-5 at 16 bits)",
                          .default_value = "3e-5",
                          .min = 0,
                          .max = 0.1},
                         {.name = "msm_quantization",
                          .description = "msm: how a texel stores its moments: float32 (128 bits) or unorm16 (the "
                                         "paper's optimized basis, 64 bits)",
                          .default_value = "float32",
                          .choices = {"float32", "unorm16"}},
                         bleed_reduction_setting()},
            .taps = no_taps,
            .texel_reads = bilinear_reads,
            .moments = {.of_depth = texel_moments,
                        .stored = stored_moments,
                        .depth_statistics = moment_statistics,
                        .mean_words = "the mean b₁ of the depth",
                        .deviation_words = "√(b₂ − b₁²)"},
            .visibility = hamburger_visibility};
}

}  // namespace shadowlab
