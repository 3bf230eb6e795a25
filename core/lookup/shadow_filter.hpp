#pragma once
// How a lookup turns a map's texels into a visibility in [0, 1]: the filters every engine ships, each
// a setting of every map method (lookup/lookup_settings.hpp), read alike by the CPU lookup
// (lookup/shadow_reader.hpp) and the GPU pass (viewer/render/shadow_map_pass.cpp). Each filter is one
// FilterDescriptor, listed once (shadow_filter.cpp) or registered later (registry/filter_registry.hpp):
// its name, its settings, its taps, its CPU visibility and its GLSL. Nothing else names a filter.
#include <deque>
#include <string>
#include <vector>
#include <glm/glm.hpp>

#include "lookup/kernel_taps.hpp"
#include "methods/settings.hpp"
#include "notes/note.hpp"

namespace shadowlab {

// A lookup's filter: which one, and the shipped filters' parameters (each read by the filters that
// list its setting).
struct ShadowFilter {
    std::string kind = "hard";          // a FilterDescriptor's name
    PcfKernel kernel = PcfKernel::box;  // pcf; pcss always takes the Poisson disk
    int kernel_size = 3;                // N: N×N taps (box, tent) or N² (poisson); pcss: N² per pass;
                                        // vsm, evsm: the blur's side in texels
    double radius_texels = 1.0;         // pcf: the kernel's half-width in the map's texels
    double radius_world = 0.0;          // pcf: the half-width in world units across the light (> 0 overrides texels)
    double min_variance = 1e-6;         // vsm, evsm: the variance's floor, in squared depth units
    double bleed_reduction = 0.0;       // vsm, evsm: linstep's cut (chebyshev.hpp)
    double evsm_positive = 40.0, evsm_negative = 5.0;  // evsm: the exponents c⁺, c⁻ (<= evsm_exponent_limit())
    double msm_moment_bias = 3e-5;  // msm: α, the moments pulled toward (½, ½, ½, ½) (Peters and Klein 2015)
    bool msm_quantized = false;     // msm: 16 bits per moment in the optimized basis (64 bits a texel)
    double esm_exponent = 80.0;     // esm: c of e^(c d) (<= esm_exponent_limit())
    Settings settings;              // the lookup settings as given (lookup_from): what a registered filter's own read

    bool reads_moments() const;  // vsm, evsm, msm, esm: the prefiltered moments (lookup/moment_map.hpp)
    bool soft() const;           // a visibility between 0 and 1 (every filter but hard)
    // Texel reads of one map lookup: 1 (hard), N² (pcf), 2 N² (pcss: search and filter), 4 (a
    // bilinear read of the prefiltered moments).
    int taps() const;
};

class ShadowReader;
struct MapReceiver;
struct Receiver;
struct LookupCount;

// What a prefiltered filter stores per texel (lookup/moment_map.hpp): the moments of the texel's
// depth, which the reader blurs over the kernel and reads bilinearly, and how they read back as a
// depth in the Shadow map view. A filter without them reads the depth texture itself.
struct MomentEncoding {
    // The moments of one depth d in [0, 1]: vsm (d, d², 0, 0); null: the filter reads no moments.
    glm::dvec4 (*of_depth)(double depth, const ShadowFilter& filter) = nullptr;
    // What a texel keeps of its blurred moments (msm's 16-bit variant rounds each to 1/65535); null:
    // the blurred moments as a float32 texture holds them.
    glm::dvec4 (*stored)(const glm::dvec4& blurred, const ShadowFilter& filter) = nullptr;
    // The mean depth the stored moments say, and their standard deviation in depth units (NaN where
    // the moments hold none: esm).
    glm::dvec2 (*depth_statistics)(const glm::dvec4& stored, const ShadowFilter& filter) = nullptr;
    std::string mean_words;       // how the view names the mean: "the mean m₁ of the depth"
    std::string deviation_words;  // and the deviation: "√(m₂ − m₁²)"; empty for none
};

struct FilterDescriptor {
    std::string name;                   // as `--set filter=` names it: lower case, digits, '_' (a GLSL name too)
    std::string description;            // one line, for the filter setting's help and the window's chooser
    std::string brief;                  // a few words after the name in the setting's help ("nearest texel"), or none
    std::vector<SettingSpec> settings;  // the lookup settings it reads besides the bias (shared ones: the same spec)
    // The taps it reads around a lookup, in its order (none for a prefiltered filter); the CPU reader
    // and the GPU pass both take this list.
    std::vector<KernelTap> (*taps)(const ShadowFilter& filter) = nullptr;
    int (*texel_reads)(const ShadowFilter& filter) = nullptr;  // per map lookup (ShadowFilter::taps)
    bool (*turns_taps)(const ShadowFilter& filter) = nullptr;  // its taps turn per pixel (pixel_rotation); null: never
    MomentEncoding moments;                                    // what the reader prefilters for it, if anything
    bool soft = true;                                          // false: 0 or 1 only (hard)
    // The CPU visibility of one map lookup, the receiver already under the map (ShadowReader::under).
    double (*visibility)(const ShadowReader& reader, const MapReceiver& m, const Receiver& r,
                         LookupCount* count) = nullptr;
    // The degradations its lookups took (PCSS: a light without size, searches clamped); null: none.
    std::vector<Note> (*fallbacks)(const ShadowReader& reader, const LookupCount& count) = nullptr;
    // Its GLSL: `float shadowFilter_<name>(int i, ShadowMapReceiver m, float rotation)`, the same
    // visibility on the GPU (viewer/render/glsl/shadow_reader.glsl declares what it may call). Empty
    // for a shipped filter: its file viewer/render/glsl/<name>_filter.glsl, which the viewer embeds.
    std::string glsl;
};

// Every filter, in the order the settings and the window list them: the shipped ones, then any
// registered later. A deque: adding one never moves the others.
const std::deque<FilterDescriptor>& all_filters();
const FilterDescriptor* find_filter(const std::string& name);
// The filter, or std::invalid_argument "unknown filter 'x' (known: hard, pcf, ...)".
const FilterDescriptor& filter_named(const std::string& name);
const FilterDescriptor& filter_of(const ShadowFilter& filter);  // filter_named(filter.kind)
// Its index in all_filters(): how the GPU pass numbers it.
int filter_index(const FilterDescriptor& descriptor);

// Appends a filter; throws std::invalid_argument for a name taken or not a GLSL name, or a missing
// function. register_filter (registry/filter_registry.hpp) calls it and updates the methods' settings.
void add_filter(FilterDescriptor descriptor);

// The taps the filter reads around a lookup (its descriptor's list).
std::vector<KernelTap> filter_taps(const ShadowFilter& filter);

}  // namespace shadowlab
