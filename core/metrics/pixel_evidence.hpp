#pragma once
// What the lookup of one misclassified pixel read, gathered once so that every cause's test
// (metrics/pixel_cause.cpp) decides from the same facts. The depths are the hard lookup's, with
// the run's biases, at the texel it reads: a filtered run is first held against that read.
#include <vector>

#include "lookup/shadow_reader.hpp"
#include "metrics/pixel_cause.hpp"
#include "metrics/shadow_error.hpp"

namespace shadowlab {

struct PixelEvidence {
    bool false_shadow = false;      // the map shadows a lit point; else it lights a shadowed one
    bool technique = false;         // a geometric technique judged it: no map was read
    bool contact_darkened = false;  // false shadow the map alone lights: the contact shadows made it
    bool reads_map = true;          // the selected map covers the (biased) point, within its depth range
    bool filtered = false;          // the run's filter is soft (not the hard one-texel read) ...
    bool hard_right = false;        // ... and the hard read with the same biases gets the pixel right
    bool seam = false;              // a blend band whose two maps' hard reads disagree, or within kSeamPixels of
                                    // the pixels of a map after this one (the next cascade) that reads it right
    double gap = 0.0;               // the hard read's receiver − stored depth: > 0 shadowed
    double step = 0.0;              // the stored depth's quantization step in the map's depth format
    // The stored depth is no nearer the light than the receiver's own plane at the texel's centre
    // (within a quarter of the plane's depth change across a texel): the texel holds the receiver.
    bool own_surface = false;
    // With no bias at all, the texel under the point holds a surface in front of the receiver's
    // plane: an occluder the biases pushed the point past.
    bool unbiased_occluder = false;
    // The exact verdict changes within the texel's footprint: for false shadow, the texel holds an
    // occluder the point does not have; for false light, a lit reference pixel lies within the
    // texel's extent in the image (m pixels) of this one.
    bool straddles_edge = false;
    bool projection_dominant = false;  // the projection factor of m exceeds both 1 and the perspective factor
};

// The cause of every pixel of a map method's run: `none` where the verdict agrees or was not
// judged. `error` is measure_shadow_error's for the same reader and reference.
std::vector<PixelCause> diagnose_pixels(const ReferenceImage& reference, const ShadowReader& reader,
                                        const ShadowError& error);

// The evidence at one misclassified pixel (x, y): what its cause was decided from (the window's
// pixel readout, the tests).
PixelEvidence evidence_of(const ReferenceImage& reference, const ShadowReader& reader, const ShadowError& error, int x,
                          int y);

// A geometric technique's wrong pixels: all `technique` (its limits name why).
std::vector<PixelCause> diagnose_technique(const ShadowError& error);

}  // namespace shadowlab
