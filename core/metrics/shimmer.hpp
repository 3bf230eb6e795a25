#pragma once
// Shimmer: shadows that flicker while the camera moves over a static scene. The receiver points the
// camera sees at the start of a path stay fixed in the world; every frame the method builds its
// maps for that frame's camera and judges each point inside the frame's view. The exact answer for a
// fixed point under a fixed light never changes, so a verdict that flips between consecutive frames
// is shimmer: the share of (point, consecutive frames) transitions whose verdict flips.
#include <vector>

#include "metrics/measurement.hpp"
#include "metrics/page_caching.hpp"
#include "scene/camera_path.hpp"

namespace shadowlab {

// A fixed world point on a receiver facing the light, seen at the path's start, and the reference's
// verdict for it.
struct ShimmerSample {
    glm::dvec3 position;
    glm::dvec3 normal;  // unit, the side the camera sees
    bool lit = false;
};

// The visible receiver pixels of the context's reference that face the light, as fixed points.
std::vector<ShimmerSample> shimmer_samples(const MeasureContext& context);

struct FrameShimmer {
    int frame = 0;
    size_t judged = 0;            // samples inside this frame's view frustum
    size_t wrong = 0;             // of those, judged otherwise than the reference
    size_t transitions = 0;       // samples judged in this frame and in the one before
    size_t flips = 0;             // of those, whose verdict changed
    std::vector<Note> fallbacks;  // what the method fell back to in this frame
    // What drawing the frame's maps costs: a virtual map's pages allocated, kept and freed since the
    // frame before (metrics/page_caching.hpp), and the texels drawn, every tile's without a cache
    // (fresh) and with one (cached: a virtual map's new pages; the same as fresh for other setups).
    PageTurnover pages;
    double texels_fresh = 0.0, texels_cached = 0.0;
};

struct Shimmer {
    std::vector<FrameShimmer> frames;

    size_t flips() const;
    size_t transitions() const;
    double share() const;  // flips / transitions (0 without transitions)
    // Texels drawn per frame after the first (the first draws everything either way): fresh and cached.
    double texels_fresh_per_frame() const;
    double texels_cached_per_frame() const;
};

// Follows `path` from the context's camera, building the method's maps at `resolution` for every
// frame and judging `samples` as the settings' filter and bias say (a constant `bias` >= 0 replaces
// the bias settings, as measure does; contact shadows march in each frame's own depth image, traced
// at the reference's size). Throws std::invalid_argument for a geometric technique: it has no map.
Shimmer measure_shimmer(const MeasureContext& context, const std::vector<ShimmerSample>& samples, const Method& method,
                        const Settings& settings, int resolution, double bias, const CameraPath& path);

}  // namespace shadowlab
