#pragma once
// One method at one resolution measured against the exact reference: the error, the cost.
// The reference is traced once per scene and camera (MeasureContext) and shared by every run.
#include <optional>
#include <string>
#include <vector>

#include "methods/method.hpp"
#include "metrics/shadow_error.hpp"
#include "reference/exact_shadows.hpp"
#include "scene/tessellation.hpp"
#include "techniques/technique.hpp"

namespace shadowlab {

struct MeasureContext {
    Scene scene;
    std::vector<ObjectBox> boxes;
    WorldTriangles triangles;
    std::vector<bool> casters;
    ReferenceImage reference;
};

MeasureContext prepare_measurement(const Scene& scene, int width, int height);

struct Measurement {
    std::string method;
    int resolution = 0;  // 0 for a technique without a map
    double bias = -1.0;  // world units; negative: slope-scaled per pixel
    ShadowError error;
    double setup_ms = 0.0, raster_ms = 0.0;
    std::optional<std::string> fallback;
    std::optional<GeometryCost> geometry;  // techniques only: polygons drawn, fragments per pixel
};

// bias: world units along the light; negative: slope-scaled per pixel (slope_scaled_bias).
Measurement measure_method(const MeasureContext& context, const Method& method, const Settings& settings,
                           int resolution, double bias);

// A geometric technique against the same reference: error, the cost of building its geometry
// (setup) and of judging the pixels (raster), its polygons and fill.
Measurement measure_technique(const MeasureContext& context, const Technique& technique, const Settings& settings);

}  // namespace shadowlab
