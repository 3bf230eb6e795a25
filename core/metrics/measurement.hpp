#pragma once
// One method at one resolution measured against the exact reference: the error, the cost.
// The reference is traced once per scene and camera (MeasureContext) and shared by every run.
#include <optional>
#include <string>
#include <vector>

#include "metrics/map_breakdown.hpp"
#include "metrics/shadow_error.hpp"
#include "metrics/storage_bound.hpp"
#include "reference/exact_shadows.hpp"
#include "registry/method.hpp"
#include "scene/tessellation.hpp"

namespace shadowlab {

struct MeasureContext {
    Scene scene;
    std::vector<ObjectBox> boxes;
    WorldTriangles triangles;
    std::vector<bool> casters;
    ReferenceImage reference;
    // The view's storage bounds (metrics/storage_bound.hpp), from the reference: only where a measure
    // reports storage (add_storage_bounds); they cost more than the reference itself.
    std::optional<StorageBounds> storage_bounds;
};

// The reference of the largest image of the camera's aspect within width x height (image_size_within):
// context.reference.width and .height say which. With an area light it is the soft reference from
// `light_samples` rays per pixel (its lit verdicts still from the light's centre).
MeasureContext prepare_measurement(const Scene& scene, int width, int height, int light_samples = kDefaultLightSamples);

// The context's storage bounds, so that every measure on it reports its storage (Measurement::storage).
void add_storage_bounds(MeasureContext& context);

struct Measurement {
    std::string method;
    int resolution = 0;        // 0 for a technique without a map
    double texels_used = 0.0;  // maps: the texels the setup's tiles (their masks' share) hold (an atlas may leave part
                               // of the texture empty)
    double bias = -1.0;        // world units, replacing the settings' bias; negative: the settings' (lookup.bias)
    ShadowError error;
    double setup_ms = 0.0, raster_ms = 0.0;
    // maps: how the lookups read them, what that cost: the moments' blur (vsm, evsm) and the lookups
    // of every receiver pixel (wall time on every core), texel reads per receiver pixel.
    ShadowLookup lookup;
    double prefilter_ms = 0.0, lookup_ms = 0.0;
    double taps_per_pixel = 0.0;
    std::vector<Note> fallbacks;           // maps: the degradations taken
    std::vector<Note> limits;              // geometric techniques: the limits met
    std::optional<GeometryCost> geometry;  // geometric techniques only: polygons drawn, fragments per pixel
    std::optional<MapBreakdown> by_map;    // setups of several maps only: per map, and the seams
    std::optional<PageTable> pages;        // a virtual map's page table (MapSelection::Rule::pages)
    std::optional<StorageFactor> storage;  // maps on a context with storage bounds: the texels its max perspective m
                                           // asks, against the view's bound

    // What the method told the user: a map's fallbacks, a technique's limits.
    const std::vector<Note>& notes() const { return geometry ? limits : fallbacks; }
};

// Another method's defaults read through these settings' filter, bias and depth format: the
// focused map a warp is held against, the map a remedy measures instead.
Settings settings_like(const Method& other, const Settings& settings);

// One method against the reference. A map method: its setup (the fastest of a few runs), its maps
// rasterized at `resolution` texels per side of the texture, read with the settings' filter and
// bias (lookup/lookup_settings.hpp; a constant `bias` >= 0, the CLI's --bias, replaces the bias
// settings). A geometric technique: the cost
// of building its geometry (setup) and of judging the pixels (raster), its polygons and fill;
// resolution and bias do not apply. A perspective warp (psm, lispsm, tsm, xpsm) is held against the
// focused map, measured on the same reference: one that misclassifies more than twice its share (and
// 0.05 percentage points more) gets a warp_loses note naming the cause and the numbers.
Measurement measure(const MeasureContext& context, const Method& method, const Settings& settings, int resolution,
                    double bias);

}  // namespace shadowlab
