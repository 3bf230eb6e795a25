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

namespace shadowlab {

struct MeasureContext {
    Scene scene;
    std::vector<ObjectBox> boxes;
    WorldTriangles triangles;
    std::vector<bool> casters;
    ReferenceImage reference;
    double default_bias = 0.0;  // 2e-4 of the scene's diagonal, in world units
};

MeasureContext prepare_measurement(const Scene& scene, int width, int height);

struct Measurement {
    std::string method;
    int resolution = 0;
    double bias = 0.0;
    ShadowError error;
    double setup_ms = 0.0, raster_ms = 0.0;
    std::optional<std::string> fallback;
};

// bias < 0 takes the context's default.
Measurement measure_method(const MeasureContext& context, const Method& method, const Settings& settings,
                           int resolution, double bias);

}  // namespace shadowlab
