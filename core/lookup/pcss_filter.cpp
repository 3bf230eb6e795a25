// Percentage-closer soft shadows (Fernando 2005): a blocker search, the penumbra the average blocker
// casts (lookup/pcss.hpp), PCF of that width, all over the Poisson disk.
#include <string>

#include "lookup/lookup_settings.hpp"
#include "lookup/pcss.hpp"
#include "lookup/shadow_reader.hpp"
#include "lookup/shipped_filters.hpp"
#include "maps/map_lookup.hpp"

namespace shadowlab {
namespace {

std::vector<KernelTap> poisson(const ShadowFilter& f) { return kernel_taps(PcfKernel::poisson, f.kernel_size); }
int two_passes(const ShadowFilter& f) { return 2 * f.kernel_size * f.kernel_size; }
bool turns(const ShadowFilter&) { return true; }

double soft_shadow(const ShadowReader& reader, const MapReceiver& m, const Receiver& r, LookupCount* count) {
    const Light& light = reader.light();
    const std::vector<KernelTap>& taps = reader.taps();
    const DepthMap& depth = reader.depth();
    // PCSS step 1: the blocker search, over the footprint of the light seen from the receiver as far
    // back as the map's near plane (d = 0), at most kMaxSearchTexels.
    const double to_near_plane = distance_back_to_depth(m.map, m.light_direction, m.position, 0.0);
    double search = blocker_search_radius(light, m.position, to_near_plane) / m.texel_world;
    if (!(search <= ShadowReader::kMaxSearchTexels)) {
        search = ShadowReader::kMaxSearchTexels;
        if (count) ++count->searches_clamped;
    }
    const double c = std::cos(r.rotation), s = std::sin(r.rotation);
    double blocker_depth = 0.0;
    int blockers = 0;
    for (const KernelTap& tap : taps) {
        const glm::ivec2 texel = reader.tap_texel(m, m.uv + rotated(tap.offset, c, s) * (search / m.texels)).texel;
        const double stored = depth.at(texel.x, texel.y);
        if (stored < m.depth) blocker_depth += stored, ++blockers;
    }
    if (count) count->taps += taps.size();
    if (blockers == 0) return 1.0;  // nothing between the receiver and the light
    blocker_depth /= blockers;
    // PCSS step 2: the penumbra the average blocker casts, w = (d_r − d_b) w_light / d_b.
    const double blocker_distance = distance_back_to_depth(m.map, m.light_direction, m.position, blocker_depth);
    const double radius = penumbra_width(light, m.position, blocker_distance) / 2.0 / m.texel_world;
    // PCSS step 3: PCF over that penumbra (never wider than the search that found its blockers).
    return reader.lit_share(m, taps, std::min(finite_or(radius, search), search), r.rotation, count);
}

// A light without size casts no penumbra; searches cut at kMaxSearchTexels, counted.
std::vector<Note> light_and_search(const ShadowReader& reader, const LookupCount& count) {
    std::vector<Note> notes;
    if (!reader.light().is_area())
        notes.push_back({NoteKind::light_without_size, "set the light's radius or angular_radius_deg"});
    if (count.searches_clamped > 0)
        notes.push_back({NoteKind::search_clamped,
                         std::to_string(count.searches_clamped) + " of " + std::to_string(count.lookups) +
                             " lookups, at " + std::to_string(int(ShadowReader::kMaxSearchTexels)) + " texels"});
    return notes;
}

}  // namespace

FilterDescriptor pcss_filter() {
    return {.name = "pcss",
            .description = "percentage-closer soft shadows: a blocker search, the penumbra it finds, PCF that wide",
            .brief = "soft shadows sized by the light",
            .settings = {kernel_size_setting()},
            .taps = poisson,
            .texel_reads = two_passes,
            .turns_taps = turns,
            .visibility = soft_shadow,
            .fallbacks = light_and_search};
}

}  // namespace shadowlab
