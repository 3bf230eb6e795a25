#include "lookup/lookup_settings.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

#include "lookup/chebyshev.hpp"

namespace shadowlab {
namespace {

constexpr int kMaxKernelSide = 9;  // 81 taps: the GPU pass's Poisson array holds as many

template <class Enum>
Enum enum_named(const std::string& name, std::initializer_list<Enum> values) {
    for (Enum e : values)
        if (name == to_string(e)) return e;
    throw std::invalid_argument("unknown choice " + name);  // resolve_settings has refused it already
}

}  // namespace

std::vector<SettingSpec> lookup_settings() {
    const double evsm_limit = evsm_exponent_limit();
    return {
        {.name = "filter",
         .description = "how a lookup reads the map: hard (nearest texel), pcf, vsm, evsm, or pcss (soft shadows "
                        "sized by the light)",
         .default_value = "hard",
         .choices = {"hard", "pcf", "vsm", "evsm", "pcss"}},
        {.name = "pcf_kernel",
         .description = "pcf: box or tent N×N taps, or a Poisson disk of N² taps turned per pixel",
         .default_value = "box",
         .choices = {"box", "tent", "poisson"}},
        {.name = "kernel_size",
         .description = "N: pcf's N×N (or N² Poisson) taps, each of pcss's two passes N² taps, vsm/evsm's blur N "
                        "texels wide",
         .default_value = "3",
         .min = 1,
         .max = kMaxKernelSide},
        {.name = "filter_radius",
         .description = "pcf: the kernel's half-width in texels of the map",
         .default_value = "1",
         .min = 0.01,
         .max = 32},
        {.name = "filter_world_radius",
         .description = "pcf: the kernel's half-width in world units across the light (0: in texels, filter_radius)",
         .default_value = "0",
         .min = 0,
         .max = 1e30,
         .length_power = 1},
        {.name = "min_variance",
         .description = "vsm, evsm: the floor of the moments' variance (squared depth units)",
         .default_value = "1e-6",
         .min = 0,
         .max = 0.01},
        {.name = "bleed_reduction",
         .description = "vsm, evsm: light bleeding reduction, Chebyshev's bound below this cut to 0 (linstep)",
         .default_value = "0",
         .min = 0,
         .max = 0.99},
        {.name = "evsm_positive",
         .description = "evsm: c+ of e^(c+ d); at most ln(FLT_MAX)/2 = 44.36, where e^(2c) overflows a float32",
         .default_value = "40",
         .min = 0.01,
         .max = evsm_limit},
        {.name = "evsm_negative",
         .description = "evsm: c- of -e^(-c- d); at most ln(FLT_MAX)/2 = 44.36",
         .default_value = "5",
         .min = 0.01,
         .max = evsm_limit},
        {.name = "bias_constant",
         .description = "depth bias: a constant, world units along the light",
         .default_value = "0",
         .min = 0,
         .max = 1e30,
         .length_power = 1},
        {.name = "bias_slope",
         .description = "depth bias: the slope-scaled bias (a texel's world width x (1 + tan θ)) times this",
         .default_value = "1",
         .min = 0,
         .max = 100},
        {.name = "bias_normal",
         .description = "normal offset: the lookup point moved along the surface normal by this many texel widths",
         .default_value = "0",
         .min = 0,
         .max = 16},
        {.name = "bias_receiver_plane",
         .description = "receiver-plane depth bias: each texel read compares with the receiver's plane at that texel",
         .default_value = "off",
         .choices = {"off", "on"}},
    };
}

bool is_lookup_setting(const std::string& name) {
    static const std::vector<SettingSpec> specs = lookup_settings();
    return std::any_of(specs.begin(), specs.end(), [&](const SettingSpec& spec) { return spec.name == name; });
}

const std::vector<std::string>& filters_reading(const std::string& setting) {
    static const std::map<std::string, std::vector<std::string>> table{
        {"filter", {"hard", "pcf", "vsm", "evsm", "pcss"}},
        {"pcf_kernel", {"pcf"}},
        {"kernel_size", {"pcf", "pcss", "vsm", "evsm"}},
        {"filter_radius", {"pcf"}},
        {"filter_world_radius", {"pcf"}},
        {"min_variance", {"vsm", "evsm"}},
        {"bleed_reduction", {"vsm", "evsm"}},
        {"evsm_positive", {"evsm"}},
        {"evsm_negative", {"evsm"}},
    };
    static const std::vector<std::string> none;
    const auto found = table.find(setting);
    return found == table.end() ? none : found->second;
}

SettingSpec lookup_setting_defaulting_to(const std::string& name, const std::string& default_value) {
    for (SettingSpec spec : lookup_settings())
        if (spec.name == name) {
            spec.default_value = default_value;
            return spec;
        }
    throw std::invalid_argument("no lookup setting named " + name);
}

ShadowLookup lookup_from(const Settings& s, double constant_bias) {
    ShadowLookup lookup{
        .filter = {.kind = enum_named(s.choice("filter"), {FilterKind::hard, FilterKind::pcf, FilterKind::vsm,
                                                           FilterKind::evsm, FilterKind::pcss}),
                   .kernel = enum_named(s.choice("pcf_kernel"), {PcfKernel::box, PcfKernel::tent, PcfKernel::poisson}),
                   .kernel_size = int(s.number("kernel_size")),
                   .radius_texels = s.number("filter_radius"),
                   .radius_world = s.number("filter_world_radius"),
                   .min_variance = s.number("min_variance"),
                   .bleed_reduction = s.number("bleed_reduction"),
                   .evsm_positive = s.number("evsm_positive"),
                   .evsm_negative = s.number("evsm_negative")},
        .bias = {.constant = s.number("bias_constant"),
                 .slope_scale = s.number("bias_slope"),
                 .normal_offset = s.number("bias_normal"),
                 .receiver_plane = s.choice("bias_receiver_plane") == "on"}};
    if (double(lookup.filter.kernel_size) != s.number("kernel_size"))
        throw std::invalid_argument("setting kernel_size=" + std::to_string(s.number("kernel_size")) +
                                    ": expected a whole number of taps");
    if (lookup.filter.reads_moments() && lookup.filter.radius_world > 0.0)
        throw std::invalid_argument(std::string("setting filter_world_radius: filter=") +
                                    to_string(lookup.filter.kind) +
                                    " blurs its moments once per map, in texels (kernel_size); set it to 0");
    if (constant_bias >= 0.0) lookup.bias = {.constant = constant_bias, .slope_scale = 0.0};
    return lookup;
}

}  // namespace shadowlab
