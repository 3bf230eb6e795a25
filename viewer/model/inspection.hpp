#pragma once
// Everything the views draw for one scene, method and map, computed once and shared by every view:
// the method's setup and step trace, the scene's triangles, and the first map rasterized on the CPU.
#include <map>
#include <string>
#include <vector>

#include "methods/method.hpp"
#include "raster/depth_map.hpp"
#include "scene/scene.hpp"
#include "scene/tessellation.hpp"

namespace shadowlab {

struct InspectionRequest {
    std::string method = "focused";
    std::map<std::string, std::string> settings;  // key -> text, checked against the method's specs
    int resolution = 1024;                        // map texels per side
    double bias = -1.0;  // world units along the light; < 0: slope-scaled per pixel
};

struct Inspection {
    Scene scene;
    const Method* method = nullptr;
    Settings settings;
    int resolution = 0;
    double bias = -1.0;  // world units along the light; < 0: slope-scaled per pixel (slope_scaled_bias)
    ShadowInputs inputs;
    ShadowSetup setup;
    Trace trace;
    WorldTriangles triangles;
    std::vector<bool> casters;  // per object
    DepthMap depth;             // setup.maps.front(), rasterized

    const ShadowMap& map() const { return setup.maps.front(); }
};

// Throws std::invalid_argument naming the method, setting or resolution at fault.
Inspection inspect_scene(const Scene& scene, const InspectionRequest& request);

}  // namespace shadowlab
