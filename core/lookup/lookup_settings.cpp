#include "lookup/lookup_settings.hpp"

#include <algorithm>
#include <deque>
#include <stdexcept>
#include <string>

#include "methods/step_figures.hpp"

namespace shadowlab {
namespace {

constexpr int kMaxKernelSide = 9;  // 81 taps: the GPU pass's Poisson array holds as many

template <class Enum>
Enum enum_named(const std::string& name, const std::vector<Enum>& values) {
    for (Enum e : values)
        if (name == to_string(e)) return e;
    throw std::invalid_argument("unknown choice " + name);  // resolve_settings has refused it already
}

// The depth format setting: every encoding's name, the first (float32) the default.
SettingSpec depth_format_setting() {
    SettingSpec spec{.name = "depth_format",
                     .description =
                         "how the map stores its depth: float32 (32-bit float), unorm24 or unorm16 "
                         "(24- or 16-bit fixed point, steps of 1/(2^N − 1))"};
    for (DepthEncoding encoding : depth_encodings()) spec.choices.push_back(to_string(encoding));
    spec.default_value = spec.choices.at(0);
    return spec;
}

// The contact shadow's settings (lookup/contact_shadow.hpp): lengths in world units, which scale
// with the scene.
std::vector<SettingSpec> contact_shadow_settings() {
    const ContactShadow defaults;
    return {{.name = "contact_length",
             .description = "contact shadows: how far the march through the camera's depth image reaches toward the "
                            "light, world units (0: off)",
             .default_value = "0",
             .min = 0,
             .max = 1e30,
             .length_power = 1},
            {.name = "contact_steps",
             .description = "contact shadows: the samples along the march",
             .default_value = std::to_string(defaults.steps),
             .min = 1,
             .max = kMaxContactSteps},
            {.name = "contact_thickness",
             .description = "contact shadows: how deep a surface of the depth image is taken to be, world units (a "
                            "sample less than this behind it is occluded)",
             .default_value = label_number(defaults.thickness),
             .min = 0,
             .max = 1e30,
             .length_power = 1}};
}

}  // namespace

SettingSpec kernel_size_setting() {
    return {.name = "kernel_size",
            .description =
                "N: pcf's N×N (or N² Poisson) taps, each of pcss's two passes N² taps, the moment filters' blur N "
                "texels wide",
            .default_value = "3",
            .min = 1,
            .max = kMaxKernelSide};
}

SettingSpec bleed_reduction_setting() {
    return {.name = "bleed_reduction",
            .description = "vsm, evsm, msm: light bleeding reduction, the lit share below this cut to 0 (linstep)",
            .default_value = "0",
            .min = 0,
            .max = 0.99};
}

// The filter setting: every filter's name, the first the default.
SettingSpec filter_setting() {
    SettingSpec spec{.name = "filter", .description = "how a lookup reads the map: "};
    const std::deque<FilterDescriptor>& filters = all_filters();
    for (size_t i = 0; i < filters.size(); ++i) {
        const FilterDescriptor& f = filters[i];
        spec.description += (i == 0                    ? ""
                             : i + 1 == filters.size() ? ", or "
                                                       : ", ") +
                            f.name + (f.brief.empty() ? "" : " (" + f.brief + ")");
        spec.choices.push_back(f.name);
    }
    spec.default_value = spec.choices.at(0);
    return spec;
}

std::vector<SettingSpec> lookup_settings() {
    std::vector<SettingSpec> specs{filter_setting()};
    for (const FilterDescriptor& f : all_filters())  // each setting once, where a filter first reads it
        for (const SettingSpec& spec : f.settings)
            if (std::none_of(specs.begin(), specs.end(), [&](const SettingSpec& s) { return s.name == spec.name; }))
                specs.push_back(spec);
    const std::vector<SettingSpec> bias{
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
    specs.insert(specs.end(), bias.begin(), bias.end());
    specs.push_back(depth_format_setting());
    specs.push_back({.name = "depth_reversed",
                     .description = "reversed Z: the map stores 1 − depth (the far plane at 0), where float32 is "
                                    "finest toward the far end",
                     .default_value = "off",
                     .choices = {"off", "on"}});
    const std::vector<SettingSpec> contact = contact_shadow_settings();
    specs.insert(specs.end(), contact.begin(), contact.end());
    return specs;
}

bool is_lookup_setting(const std::string& name) {
    const std::vector<SettingSpec> specs = lookup_settings();  // afresh: a filter registered since adds its own
    return std::any_of(specs.begin(), specs.end(), [&](const SettingSpec& spec) { return spec.name == name; });
}

std::vector<std::string> filters_reading(const std::string& setting) {
    std::vector<std::string> names;
    for (const FilterDescriptor& f : all_filters())
        if (setting == "filter" || std::any_of(f.settings.begin(), f.settings.end(),
                                               [&](const SettingSpec& spec) { return spec.name == setting; }))
            names.push_back(f.name);
    return names;
}

SettingSpec lookup_setting_defaulting_to(const std::string& name, const std::string& default_value) {
    for (SettingSpec spec : lookup_settings())
        if (spec.name == name) {
            spec.default_value = default_value;
            return spec;
        }
    throw std::invalid_argument("no lookup setting named " + name);
}

std::map<std::string, std::string> depth_format_settings(const DepthFormat& format) {
    return {{"depth_format", to_string(format.encoding)}, {"depth_reversed", format.reversed ? "on" : "off"}};
}

ShadowLookup lookup_from(const Settings& s, double constant_bias) {
    ShadowLookup lookup{.filter = {.kind = filter_named(s.choice("filter")).name,
                                   .kernel = enum_named<PcfKernel>(
                                       s.choice("pcf_kernel"), {PcfKernel::box, PcfKernel::tent, PcfKernel::poisson}),
                                   .kernel_size = int(s.number("kernel_size")),
                                   .radius_texels = s.number("filter_radius"),
                                   .radius_world = s.number("filter_world_radius"),
                                   .min_variance = s.number("min_variance"),
                                   .bleed_reduction = s.number("bleed_reduction"),
                                   .evsm_positive = s.number("evsm_positive"),
                                   .evsm_negative = s.number("evsm_negative"),
                                   .msm_moment_bias = s.number("msm_moment_bias"),
                                   .msm_quantized = s.choice("msm_quantization") == "unorm16",
                                   .esm_exponent = s.number("esm_exponent"),
                                   .settings = s},
                        .bias = {.constant = s.number("bias_constant"),
                                 .slope_scale = s.number("bias_slope"),
                                 .normal_offset = s.number("bias_normal"),
                                 .receiver_plane = s.choice("bias_receiver_plane") == "on"},
                        .format = {.encoding = enum_named(s.choice("depth_format"), depth_encodings()),
                                   .reversed = s.choice("depth_reversed") == "on"},
                        .contact = {.length = s.number("contact_length"),
                                    .steps = int(s.number("contact_steps")),
                                    .thickness = s.number("contact_thickness")}};
    if (double(lookup.filter.kernel_size) != s.number("kernel_size"))
        throw std::invalid_argument("setting kernel_size=" + std::to_string(s.number("kernel_size")) +
                                    ": expected a whole number of taps");
    if (double(lookup.contact.steps) != s.number("contact_steps"))
        throw std::invalid_argument("setting contact_steps=" + std::to_string(s.number("contact_steps")) +
                                    ": expected a whole number of samples");
    if (lookup.filter.reads_moments() && lookup.filter.radius_world > 0.0)
        throw std::invalid_argument("setting filter_world_radius: filter=" + lookup.filter.kind +
                                    " blurs its moments once per map, in texels (kernel_size); set it to 0");
    if (constant_bias >= 0.0) lookup.bias = {.constant = constant_bias, .slope_scale = 0.0};
    return lookup;
}

}  // namespace shadowlab
