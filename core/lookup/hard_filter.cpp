// Hard shadows: the nearest texel against the receiver's depth, 0 or 1.
#include "lookup/shadow_reader.hpp"
#include "lookup/shipped_filters.hpp"

namespace shadowlab {
namespace {

std::vector<KernelTap> centre_tap(const ShadowFilter&) { return {{glm::dvec2(0.0), 1.0}}; }
int one_read(const ShadowFilter&) { return 1; }

// Its one tap at the centre, which no radius moves.
double nearest_texel(const ShadowReader& reader, const MapReceiver& m, const Receiver&, LookupCount* count) {
    return reader.lit_share(m, reader.taps(), 0.0, 0.0, count);
}

}  // namespace

FilterDescriptor hard_filter() {
    return {.name = "hard",
            .description = "the nearest texel against the receiver's depth: lit or shadowed",
            .brief = "nearest texel",
            .taps = centre_tap,
            .texel_reads = one_read,
            .soft = false,
            .visibility = nearest_texel};
}

}  // namespace shadowlab
