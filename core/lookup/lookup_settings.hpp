#pragma once
// The settings every map method shares, beside its own: the filter and the depth bias its lookups
// apply, and the depth format its maps are stored in. The registry appends them to each map method's list, so that the
// CLI (--set filter=pcss), the window's controls and the tests read one declaration.
#include <map>
#include <string>
#include <vector>

#include "lookup/contact_shadow.hpp"
#include "lookup/depth_bias.hpp"
#include "lookup/shadow_filter.hpp"
#include "methods/settings.hpp"
#include "raster/depth_format.hpp"

namespace shadowlab {

// How a point reads a setup's maps.
struct ShadowLookup {
    ShadowFilter filter;
    DepthBias bias;
    DepthFormat format;  // how the maps store their depth: every raster for this lookup draws in it
    ContactShadow
        contact;  // the march in the camera's depth image that multiplies the maps' visibility; off by default
};

// Every filter's settings (the filter, then each filter's own, in the filters' order), the depth
// bias's, the depth format's (depth_format, depth_reversed) and the contact shadow's (contact_length,
// contact_steps, contact_thickness). A filter registered later adds its own.
std::vector<SettingSpec> lookup_settings();

// Whether `name` is one of lookup_settings(), and of those, the filters that read a filter setting
// ("kernel_size": pcf, vsm, evsm, pcss); empty for a depth-bias or depth-format setting, which every
// filter reads.
bool is_lookup_setting(const std::string& name);
std::vector<std::string> filters_reading(const std::string& setting);

// The kernel's side N, which several filters read (their descriptors share this spec).
SettingSpec kernel_size_setting();
// Light bleeding reduction (lookup/chebyshev.hpp), which vsm, evsm and msm read.
SettingSpec bleed_reduction_setting();

// One of them with another default: a method whose maps read best with it declares it among its own
// settings, and the registry then leaves the shared one out.
SettingSpec lookup_setting_defaulting_to(const std::string& name, const std::string& default_value);

// The settings (key -> text) that ask for a depth format: depth_format and depth_reversed.
std::map<std::string, std::string> depth_format_settings(const DepthFormat& format);

// The lookup the settings ask for. `constant_bias` >= 0 (the CLI's --bias B) replaces the bias
// settings with that constant alone. Throws std::invalid_argument naming the setting for a
// combination the ranges cannot refuse alone (a prefiltered VSM kernel in world units).
ShadowLookup lookup_from(const Settings& settings, double constant_bias = -1.0);

}  // namespace shadowlab
