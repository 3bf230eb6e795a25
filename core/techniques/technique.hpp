#pragma once
// A geometric shadow technique: not a shadow map but geometry built from the casters and the
// light (shadow volumes, planar projection), judged per camera pixel. A pure function of the scene,
// its triangles, the camera image's visible points and the settings, like a map Method.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "methods/settings.hpp"
#include "reference/exact_shadows.hpp"
#include "scene/tessellation.hpp"
#include "trace/trace.hpp"

namespace shadowlab {

// What drawing the technique's geometry costs on a GPU: how many polygons, and how many fragments
// of them land on each camera pixel (over the whole image: mean and max).
struct GeometryCost {
    std::size_t polygons = 0;
    double fill_mean = 0.0, fill_max = 0.0;
};

// The cost of `polygons` polygons that drew `fragments[i]` fragments on pixel i.
GeometryCost geometry_cost(std::size_t polygons, const std::vector<int>& fragments);

// Limits met, each a fallback::named text, as one fallback: nullopt when there are none.
std::optional<std::string> joined_limits(const std::vector<std::string>& limits);

struct TechniqueResult {
    std::vector<uint8_t> shadowed;        // per pixel of the image: 1 where the visible point is in shadow
    GeometryCost cost;
    std::optional<std::string> fallback;  // the limits met, each named (fallbacks.hpp), "; "-joined
    double setup_ms = 0.0;                // building the geometry
    double raster_ms = 0.0;               // judging the pixels (the stencil or projection pass)
};

struct Technique {
    std::string name;         // as on the command line: "volumes"
    std::string title;        // "Stencil shadow volumes"
    std::string description;  // one line
    std::vector<SettingSpec> settings;
    // `image` gives the visible point of each pixel (position, visible, object); its lit and
    // facing fields are not read.
    TechniqueResult (*compute)(const Scene& scene, const WorldTriangles& triangles, const ReferenceImage& image,
                               const Settings& settings, Trace* trace);
};

// All techniques, in the order the UI lists them (after the map methods).
const std::vector<Technique>& all_techniques();
// Nullptr when no technique has that name.
const Technique* find_technique(const std::string& name);

}  // namespace shadowlab
