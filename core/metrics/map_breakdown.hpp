#pragma once
// A setup of several maps (cascades, an atlas) judged map by map: the receiver pixels each map
// serves, how many of them it misclassifies and its perspective aliasing; and the seams: the share
// of all misclassified pixels lying within a few pixels of a boundary between two maps' pixels.
#include <vector>

#include "metrics/shadow_error.hpp"

namespace shadowlab {

struct MapShare {
    size_t pixels = 0;         // receiver pixels this map serves
    size_t misclassified = 0;  // of them
    AliasingStats m_perspective;
};

struct MapBreakdown {
    std::vector<MapShare> maps;  // indexed like setup.maps
    size_t misclassified = 0;    // receiver pixels some map serves, all maps
    size_t near_seams = 0;       // of them, within seam_pixels of a boundary between maps

    double seam_share() const { return misclassified ? static_cast<double>(near_seams) / misclassified : 0.0; }
};

constexpr int kSeamPixels = 3;

// From the error already measured (its verdicts and m_perspective image) and the setup's selection
// for each receiver pixel's visible point.
MapBreakdown break_down_by_map(const ReferenceImage& reference, const ShadowError& error, const ShadowSetup& setup,
                               int seam_pixels = kSeamPixels);

}  // namespace shadowlab
